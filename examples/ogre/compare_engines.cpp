/* The target comparison: the worst measured sigma (screen pixels per texel,
 * largest singular value, swarp_measure_points / swarp_measure_max) of
 * OGRE 1.12's and OSG 3.6's shadow matrices and of this library's defaults,
 * on one scene, every matrix measured by the same library function.
 *
 * Scene: a 200 x 30 x 200 m box S = [-100, 100] x [-30, 0] x [-100, 100],
 * the eye 2 m above the centre of its top face looking horizontally along -z,
 * fovy 60 deg, aspect 4/3 (1024 x 768 screen), near 0.5, far 200 and 1000,
 * 1024^2 maps.  Light at gamma from the view direction (gamma = angle between
 * the view direction and the direction TO the light, in the vertical plane of
 * the view: 0 = low sun straight ahead, exactly parallel; 90 = overhead; 150 =
 * sun behind and above).
 *
 * Receiver sets (each sigma the maximum over the set):
 *   axis     AXIS_SAMPLES points on the view axis, geometric over the adjusted
 *            range [RHS] §3.3.1, bisector normals;
 *   frustum  swarp_measure_max over V ∩ S (bisector receivers), per map over
 *            its depth range;
 *   ground   points of the top face y = 0 (normal +y) seen through a
 *            GROUND_COLS x GROUND_ROWS lattice of screen pixels.
 * A point counts for the map whose depth range holds its planar depth (the
 * split it belongs to); points that do not project into that map are counted
 * as "out" and shown beside the value.
 *
 *   compare-engines [--commit ID]   the markdown table (docs/engines-compare.md)
 *   compare-engines --check         the machinery checks (meson test) */
#include "headless.h"
#include "ogre_scene.h"

#include <OgreShadowCameraSetupFocused.h>
#include <OgreShadowCameraSetupLiSPSM.h>
#include <OgreShadowCameraSetupPSSM.h>

#ifdef SWARP_HAVE_OSG
#include <osg/Camera>
#include <osg/Polytope>
#include <osgShadow/ConvexPolyhedron>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#endif

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

using swarp_ogre_test::HeadlessRoot;
using swarp_ogre_test::HeadlessSceneManager;
using swarp_ogre_test::SizedTarget;

namespace {

const double PI = 3.14159265358979323846;
const double EYE_Y = 2, EYE_Z = 0, FOVY_DEG = 60, Z_NEAR = 0.5;
const unsigned SCREEN_W = 1024, SCREEN_H = 768, MAP = 1024, SPLITS = 4;
const swarp_aabb BOX = {{-100, -30, -100}, {100, 0, 100}};
const double FARS[] = {200, 1000};
const double GAMMAS_DEG[] = {90, 60, 45, 30, 20, 5, 0, 150};
/* view-axis samples: 4 per octave of a 0.5..200 m range, and more */
const unsigned AXIS_SAMPLES = 256;
/* |e + l|^2 below which the bisector of the unit directions to the eye and
 * to the light is taken as undefined: they are antiparallel to within 1e-6
 * rad, where rounding (1e-16) of the sum would decide its direction */
const double BISECTOR_MIN_SQ = 1e-12;
/* ground lattice: one sample per 8 x 8 screen pixels */
const unsigned GROUND_COLS = 128, GROUND_ROWS = 96;

/* A set of shadow maps: map i serves planar depths [z[i], z[i+1]). */
struct Maps {
    unsigned count;
    int state; /* 0 usable, 1 non-finite matrices, 2 the engine aborted, 3 not built */
    swarp_mat4 m[SPLITS];
    double z[SPLITS + 1];
};

struct Sigma {
    double axis, frustum, ground;
    unsigned out_axis, out_ground, out_frustum;
    int state;
};

swarp_camera makeCamera(double z_far)
{
    swarp_camera c = swarp_camera();
    c.eye = {0, EYE_Y, EYE_Z};
    c.dir = {0, 0, -1};
    c.up = {0, 1, 0};
    c.fovy = FOVY_DEG * PI / 180;
    c.aspect = double(SCREEN_W) / SCREEN_H;
    c.z_near = Z_NEAR;
    c.z_far = z_far;
    return c;
}

swarp_measure_res resolution()
{
    swarp_measure_res r = {SCREEN_W, SCREEN_H, MAP, MAP};
    return r;
}

swarp_vec3 sub(swarp_vec3 a, swarp_vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
swarp_vec3 add(swarp_vec3 a, swarp_vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
swarp_vec3 scale(swarp_vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(swarp_vec3 a, swarp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
swarp_vec3 unit(swarp_vec3 a) { return scale(a, 1 / std::sqrt(dot(a, a))); }

/* the receivers of one configuration */
struct Receivers {
    std::vector<swarp_vec3> axis_p, axis_n, ground_p, ground_n;
};

Receivers makeReceivers(const swarp_camera& cam, swarp_vec3 to_light, double adj_near, double adj_far)
{
    Receivers r;
    for (unsigned i = 0; i < AXIS_SAMPLES; ++i) {
        double t = adj_near * std::pow(adj_far / adj_near, double(i) / (AXIS_SAMPLES - 1));
        swarp_vec3 p = add(cam.eye, scale(cam.dir, t));
        /* bisector of the directions to the eye and to the light; with the
         * light straight into the eye they cancel and the receiver is taken
         * facing up, like the ground */
        swarp_vec3 b = add(unit(sub(cam.eye, p)), to_light);
        r.axis_p.push_back(p);
        r.axis_n.push_back(dot(b, b) > BISECTOR_MIN_SQ ? unit(b) : swarp_vec3{0, 1, 0});
    }
    double ty = std::tan(cam.fovy / 2), tx = ty * cam.aspect;
    for (unsigned row = 0; row < GROUND_ROWS; ++row)
        for (unsigned col = 0; col < GROUND_COLS; ++col) {
            double nx = -1 + (2 * col + 1.0) / GROUND_COLS, ny = -1 + (2 * row + 1.0) / GROUND_ROWS;
            /* the ray through the pixel, planar depth 1 (right = +x, up = +y) */
            swarp_vec3 ray = {nx * tx, ny * ty, -1};
            if (ray.y >= 0)
                continue;
            double depth = (BOX.max.y - cam.eye.y) / ray.y;
            swarp_vec3 p = add(cam.eye, scale(ray, depth));
            if (depth < adj_near || depth > adj_far || p.x < BOX.min.x || p.x > BOX.max.x ||
                p.z < BOX.min.z || p.z > BOX.max.z)
                continue;
            p.y = BOX.max.y;
            r.ground_p.push_back(p);
            r.ground_n.push_back({0, 1, 0});
        }
    return r;
}

/* worst sigma over points, each measured with the map of its depth */
double pointsSigma(const swarp_camera& cam, const Maps& maps, const std::vector<swarp_vec3>& p,
                   const std::vector<swarp_vec3>& n, unsigned* out)
{
    swarp_measure_res res = resolution();
    double worst = 0;
    *out = 0;
    for (size_t k = 0; k < p.size(); ++k) {
        double depth = dot(sub(p[k], cam.eye), cam.dir);
        unsigned i = 0;
        while (i + 1 < maps.count && depth >= maps.z[i + 1])
            ++i;
        swarp_texel_error e;
        swarp_status st = swarp_measure_points(&cam, &maps.m[i], &res, &p[k], &n[k], 1, &e);
        if (swarp_status_is_error(st))
            return NAN;
        if (e.flags & SWARP_TEXEL_SINGULAR)
            worst = INFINITY;
        else if (e.flags & SWARP_TEXEL_INSIDE)
            worst = std::fmax(worst, e.sigma);
        else
            ++*out;
    }
    return worst;
}

Sigma measureMaps(const swarp_camera& cam, const swarp_light& light, const Maps& maps,
                  const Receivers& r, double adj_near, double adj_far)
{
    Sigma s = {NAN, NAN, NAN, 0, 0, 0, maps.state};
    if (maps.state != 0)
        return s;
    s.axis = pointsSigma(cam, maps, r.axis_p, r.axis_n, &s.out_axis);
    s.ground = pointsSigma(cam, maps, r.ground_p, r.ground_n, &s.out_ground);
    swarp_measure_res res = resolution();
    s.frustum = 0;
    for (unsigned i = 0; i < maps.count; ++i) {
        double z0 = std::fmax(maps.z[i], adj_near), z1 = std::fmin(maps.z[i + 1], adj_far);
        if (!(z0 < z1))
            continue;
        swarp_measured_error e;
        swarp_status st = swarp_measure_max(&cam, z0, z1, &light, &BOX, &maps.m[i], &res, nullptr, &e);
        if (st == SWARP_ERR_BODY_EMPTY)
            continue;
        if (swarp_status_is_error(st)) {
            s.frustum = NAN;
            break;
        }
        s.frustum = std::fmax(s.frustum, e.max_sigma);
        s.out_frustum += e.outside;
    }
    return s;
}

/* ---- OGRE ------------------------------------------------------------- */

struct Frame {
    HeadlessSceneManager* sm;
    Ogre::Camera* cam;
    Ogre::Viewport* vp;
    Ogre::Light* light;
};

/* OGRE's shadow cameras after two frames of the shadow loop (the first
 * leaves the visible bounds its focused setups read in the second), read as
 * projection x view of each texture camera: OGRE's world -> light clip
 * matrix with OpenGL's [-1, 1] depth (the null render system keeps the
 * projection as OGRE builds it).  In a child process: OGRE 1.12's focused
 * setups abort on some inputs (an assertion in transformToUnitCube). */
Maps ogreMaps(Frame& f, const Ogre::ShadowCameraSetupPtr& setup, unsigned textures,
              const std::vector<double>& z)
{
    Maps r = Maps();
    r.count = textures;
    r.state = 2;
    for (unsigned i = 0; i <= textures; ++i)
        r.z[i] = z[i];
    int fds[2];
    if (pipe(fds) != 0)
        return r;
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, 2);
        f.sm->resetShadowCameras();
        f.sm->setShadowTextureCountPerLightType(Ogre::Light::LT_DIRECTIONAL, textures);
        f.light->setCustomShadowCameraSetup(setup);
        f.sm->renderShadows(f.cam, f.vp);
        f.sm->renderShadows(f.cam, f.vp);
        r.state = 0;
        for (unsigned i = 0; i < textures; ++i) {
            Ogre::Matrix4 m = swarp_ogre_test::shadowViewProj(f.sm, i);
            if (!swarp_ogre_test::matFinite(m))
                r.state = 1;
            r.m[i] = swarp_ogre_test::matFromOgre(m);
        }
        ssize_t w = write(fds[1], &r, sizeof r);
        _exit(w == ssize_t(sizeof r) ? 0 : 1);
    }
    close(fds[1]);
    Maps got;
    ssize_t n = read(fds[0], &got, sizeof got);
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (n == ssize_t(sizeof got) && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0)
        return got;
    return r;
}

/* ---- OSG -------------------------------------------------------------- */

#ifdef SWARP_HAVE_OSG
/* OSG 3.6's LiSPSM as LightSpacePerspectiveShadowMapVB computes it for one
 * frame (src/osgShadow/MinimalShadowMap.cpp, StandardShadowMap.cpp,
 * ProjectionShadowMap): the receiving hull = scene bounds cut by the main
 * camera's frustum (cullShadowReceivingScene), the shadow camera aimed along
 * the light at the hull's bounding sphere with an orthographic projection
 * and the camera's forward vector as up (aimShadowCastingCamera, lightUp
 * zero), the hull cut by that frustum, then
 * LightSpacePerspectiveShadowMapAlgorithm on (hull, main camera, shadow
 * camera), then the projection trimmed to the hull's light-clip bounds
 * (frameShadowCastingCamera, trimProjection, minLightMargin 0).  The default
 * ..DB variant narrows the hull to bounds read back from a rendered frame,
 * which needs a GPU; for this scene the VB hull is what a frame sees of the
 * box.  Result: shadow view x projection (OSG row vectors) as a column-major
 * world -> light clip matrix, OpenGL's [-1, 1] depth. */
Maps osgMaps(const swarp_camera& c, swarp_vec3 light_dir, double adj_near, double adj_far)
{
    Maps r = Maps();
    r.count = 1;
    r.z[0] = adj_near;
    r.z[1] = adj_far;
    osg::Vec3d eye(c.eye.x, c.eye.y, c.eye.z), dir(c.dir.x, c.dir.y, c.dir.z), up(c.up.x, c.up.y, c.up.z);
    osg::ref_ptr<osg::Camera> mainCam = new osg::Camera;
    mainCam->setViewMatrixAsLookAt(eye, eye + dir, up);
    mainCam->setProjectionMatrixAsPerspective(FOVY_DEG, c.aspect, c.z_near, c.z_far);
    osgShadow::ConvexPolyhedron hull;
    hull.setToBoundingBox(osg::BoundingBox(BOX.min.x, BOX.min.y, BOX.min.z, BOX.max.x, BOX.max.y, BOX.max.z));
    {
        osg::Polytope frustum;
        frustum.setToUnitFrustum();
        frustum.transformProvidingInverse(mainCam->getViewMatrix() * mainCam->getProjectionMatrix());
        hull.cut(frustum);
    }
    osgShadow::ConvexPolyhedron::Vertices pts;
    hull.getPoints(pts);
    osg::BoundingBox bb;
    for (const auto& p : pts)
        bb.expandBy(p);
    osg::BoundingSphere bs(bb);
    osg::Vec3 lightDir(float(light_dir.x), float(light_dir.y), float(light_dir.z));
    osg::Vec3 lightUp(float(c.dir.x), float(c.dir.y), float(c.dir.z));
    /* StandardShadowMap::ViewData::aimShadowCastingCamera, directional */
    osg::Vec3d position = bs.center() - lightDir * bs.radius() * 2;
    float centerDistance = (position - bs.center()).length();
    float znear = centerDistance - bs.radius(), zfar = centerDistance + bs.radius();
    if (znear < zfar * 0.001f)
        znear = zfar * 0.001f;
    osg::ref_ptr<osg::Camera> shadowCam = new osg::Camera;
    float top = bs.radius();
    shadowCam->getProjectionMatrix().makeOrtho(-top, top, -top, top, znear, zfar);
    shadowCam->getViewMatrix().makeLookAt(position, bs.center(), lightUp);
    {
        osg::Matrix mvp = shadowCam->getViewMatrix() * shadowCam->getProjectionMatrix();
        osg::Polytope lf;
        lf.setToBoundingBox(osg::BoundingBox(-1, -1, -1, 1, 1, 1));
        lf.transformProvidingInverse(mvp);
        hull.cut(lf);
    }
    osgShadow::LightSpacePerspectiveShadowMapAlgorithm lispsm;
    lispsm(&hull, mainCam.get(), shadowCam.get());
    {
        osg::Matrix mvp = shadowCam->getViewMatrix() * shadowCam->getProjectionMatrix();
        pts.clear();
        hull.getPoints(pts);
        osg::BoundingBox lb;
        for (const auto& p : pts)
            lb.expandBy(p * mvp);
        if (lb.valid())
            shadowCam->getProjectionMatrix().postMult(osg::Matrix::ortho(
                lb._min[0], lb._max[0], lb._min[1], lb._max[1], -lb._min[2], -lb._max[2]));
    }
    osg::Matrixd vp = shadowCam->getViewMatrix() * shadowCam->getProjectionMatrix();
    r.state = 0;
    for (int i = 0; i < 16; ++i) {
        r.m[0].m[i] = vp.ptr()[i];
        if (!std::isfinite(r.m[0].m[i]))
            r.state = 1;
    }
    return r;
}
#endif

/* ---- this library ----------------------------------------------------- */

swarp_setup_options libOptions()
{
    swarp_setup_options o = swarp_setup_options();
    o.map_width = o.map_height = MAP;
    o.screen_width = SCREEN_W;
    o.screen_height = SCREEN_H;
    return o;
}

Maps libSingle(const swarp_camera& cam, const swarp_light& light, const swarp_setup_options& o,
               double adj_near, double adj_far)
{
    Maps r = Maps();
    r.count = 1;
    r.state = 3;
    r.z[0] = adj_near;
    r.z[1] = adj_far;
    swarp_setup_result res;
    if (swarp_status_is_error(swarp_setup(&cam, &light, &BOX, &o, &res, nullptr, 0, nullptr)))
        return r;
    r.m[0] = res.matrix;
    r.state = 0;
    return r;
}

/* the default cascade: zeroed options but the resolutions, SPLITS splits */
Maps libCascade(const swarp_camera& cam, const swarp_light& light)
{
    Maps r = Maps();
    r.state = 3;
    swarp_cascade_options co = swarp_cascade_options();
    co.setup = libOptions();
    co.split.count = SPLITS;
    swarp_cascade_result cres;
    swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
    size_t count = 0;
    swarp_status st = swarp_cascade_setup(&cam, &light, &BOX, &co, &cres, sp, SWARP_CASCADE_MAX_SPLITS, &count);
    if (swarp_status_is_error(st) || count != SPLITS)
        return r;
    r.count = SPLITS;
    for (unsigned i = 0; i < SPLITS; ++i) {
        r.m[i] = sp[i].matrix;
        r.z[i] = sp[i].z_near;
        r.z[i + 1] = sp[i].z_far;
    }
    r.state = 0;
    return r;
}

/* ---- the comparison ---------------------------------------------------- */

enum Column { OGRE_FOCUSED, OGRE_LISPSM, OGRE_PSSM, OSG_LISPSM, LIB_DEFAULT, LIB_UNIFORM, LIB_NOPT,
              LIB_CASCADE, COLUMNS };
const char* const COLUMN_NAMES[COLUMNS] = {"OGRE focused", "OGRE LiSPSM", "OGRE PSSM(4) λ 0.95",
                                           "OSG LiSPSM", "swarp default", "swarp uniform",
                                           "swarp LiSPSM n_opt", "swarp cascade(4) default"};

struct Scene {
    HeadlessRoot root;
    HeadlessSceneManager* sm;
    Ogre::Camera* cam;
    Ogre::SceneNode* lightNode;
    Ogre::Light* light;
    SizedTarget window{"window", SCREEN_W, SCREEN_H};
    Ogre::Viewport* vp;
    Scene()
    {
        sm = new HeadlessSceneManager("compare");
        sm->setShadowTechnique(Ogre::SHADOWTYPE_TEXTURE_MODULATIVE);
        sm->createShadowCameras(SPLITS, MAP);
        swarp_ogre_test::addBoxObject(sm, "box", BOX);
        cam = sm->createCamera("main");
        Ogre::SceneNode* camNode = sm->getRootSceneNode()->createChildSceneNode();
        camNode->attachObject(cam);
        camNode->setPosition(0, Ogre::Real(EYE_Y), Ogre::Real(EYE_Z));
        cam->setFOVy(Ogre::Degree(Ogre::Real(FOVY_DEG)));
        cam->setAspectRatio(Ogre::Real(double(SCREEN_W) / SCREEN_H));
        cam->setNearClipDistance(Ogre::Real(Z_NEAR));
        vp = window.addViewport(cam);
        light = sm->createLight("sun");
        light->setType(Ogre::Light::LT_DIRECTIONAL);
        lightNode = sm->getRootSceneNode()->createChildSceneNode();
        lightNode->attachObject(light);
    }
    ~Scene()
    {
        light->setCustomShadowCameraSetup(Ogre::ShadowCameraSetupPtr());
        delete sm;
    }
    /* the light travelling along -to_light; exact quaternions for the exact
     * directions (-y overhead, +z parallel to the view) */
    swarp_vec3 setLight(double gamma_deg)
    {
        lightNode->setOrientation(Ogre::Quaternion::IDENTITY);
        if (gamma_deg == 90) {
            lightNode->setOrientation(Ogre::Quaternion(0.5f, -0.5f, -0.5f, -0.5f));
        } else if (gamma_deg == 0) {
            lightNode->setOrientation(Ogre::Quaternion(0, 0, 1, 0));
        } else {
            double g = gamma_deg * PI / 180;
            lightNode->setDirection(Ogre::Vector3(0, Ogre::Real(-std::sin(g)), Ogre::Real(std::cos(g))),
                                    Ogre::Node::TS_WORLD);
        }
        lightNode->_update(true, false);
        Ogre::Vector3 d = light->getDerivedDirection();
        return {d.x, d.y, d.z};
    }
};

struct Row {
    double far, gamma_deg, gamma_lib_deg;
    Sigma s[COLUMNS];
};

Row evaluate(Scene& sc, double z_far, double gamma_deg, const Ogre::ShadowCameraSetupPtr setups[3],
             Ogre::PSSMShadowCameraSetup* pssm)
{
    Row row = Row();
    row.far = z_far;
    row.gamma_deg = gamma_deg;
    swarp_camera cam = makeCamera(z_far);
    sc.cam->setFarClipDistance(Ogre::Real(z_far));
    sc.sm->setShadowFarDistance(Ogre::Real(z_far));
    pssm->calculateSplitPoints(SPLITS, Ogre::Real(Z_NEAR), Ogre::Real(z_far));
    /* OGRE's, OSG's and the library's light: OGRE's derived (float) direction */
    swarp_light light = swarp_light();
    light.type = SWARP_LIGHT_DIRECTIONAL;
    light.direction = sc.setLight(gamma_deg);
    double adj_near = Z_NEAR, adj_far = z_far;
    swarp_body_adjusted_range(&cam, &BOX, &adj_near, &adj_far);
    Receivers rec = makeReceivers(cam, unit(scale(light.direction, -1)), adj_near, adj_far);
    Frame f = {sc.sm, sc.cam, sc.vp, sc.light};
    Maps maps[COLUMNS];
    std::vector<double> whole = {adj_near, adj_far};
    maps[OGRE_FOCUSED] = ogreMaps(f, setups[0], 1, whole);
    maps[OGRE_LISPSM] = ogreMaps(f, setups[1], 1, whole);
    const Ogre::PSSMShadowCameraSetup::SplitPointList& op = pssm->getSplitPoints();
    maps[OGRE_PSSM] = ogreMaps(f, setups[2], SPLITS, std::vector<double>(op.begin(), op.end()));
#ifdef SWARP_HAVE_OSG
    maps[OSG_LISPSM] = osgMaps(cam, light.direction, adj_near, adj_far);
#else
    maps[OSG_LISPSM] = Maps();
    maps[OSG_LISPSM].state = 3;
#endif
    swarp_setup_options o = libOptions();
    swarp_setup_result res;
    row.gamma_lib_deg = swarp_status_is_error(swarp_setup(&cam, &light, &BOX, &o, &res, nullptr, 0, nullptr))
                            ? NAN : res.gamma * 180 / PI;
    maps[LIB_DEFAULT] = libSingle(cam, light, o, adj_near, adj_far);
    o.technique = SWARP_TECHNIQUE_UNIFORM;
    maps[LIB_UNIFORM] = libSingle(cam, light, o, adj_near, adj_far);
    o.technique = SWARP_TECHNIQUE_LISPSM;
    o.param = SWARP_WARP_PARAM_NOPT;
    maps[LIB_NOPT] = libSingle(cam, light, o, adj_near, adj_far);
    maps[LIB_CASCADE] = libCascade(cam, light);
    for (int c = 0; c < COLUMNS; ++c)
        row.s[c] = measureMaps(cam, light, maps[c], rec, adj_near, adj_far);
    return row;
}

/* the worst of the three sets; +inf for a map that is unusable.  Sets in
 * which both sides of a comparison are infinite (ground receivers grazed by
 * a light exactly parallel to them: no map samples them) are left out of
 * both, so the verdict rests on the sets some map can resolve. */
double worst(const Sigma& s, const Sigma& other)
{
    if (s.state != 0)
        return INFINITY;
    double v[3] = {s.axis, s.frustum, s.ground}, o[3] = {other.axis, other.frustum, other.ground};
    double w = 0;
    for (int i = 0; i < 3; ++i) {
        if (std::isnan(v[i]))
            return INFINITY;
        if (!(std::isinf(v[i]) && (other.state != 0 || std::isinf(o[i]))))
            w = std::fmax(w, v[i]);
    }
    return w;
}

std::string num(double v, unsigned out)
{
    char b[48];
    if (std::isinf(v))
        std::snprintf(b, sizeof b, "inf");
    else
        std::snprintf(b, sizeof b, "%.3g", v);
    std::string r = b;
    if (out)
        r += "<sup>" + std::to_string(out) + " out</sup>";
    return r;
}

std::string cell(const Sigma& s)
{
    switch (s.state) {
    case 1: return "non-finite";
    case 2: return "aborts";
    case 3: return "n/a";
    default: break;
    }
    return num(s.axis, s.out_axis) + " / " + num(s.frustum, s.out_frustum) + " / " +
           num(s.ground, s.out_ground);
}

std::string verdict(double mine, double theirs)
{
    char b[96];
    std::snprintf(b, sizeof b, "%s (%.5g vs %.5g)", mine <= theirs ? "yes" : "**no**", mine, theirs);
    return b;
}

void printTable(const std::vector<Row>& rows, const char* commit)
{
    std::printf("Produced at commit %s by `sh docs/plots/compare_engines.sh` "
                "(examples/ogre/compare_engines.cpp).\n\n", commit);
    std::printf("Each cell: worst σ on the view axis / over the frustum ∩ box (bisector "
                "receivers) / on the ground (top face, normal +y); screen pixels per texel, "
                "largest singular value, %u x %u screen, %u² maps. "
                "<sup>k out</sup>: k samples of that set do not project into the map that "
                "serves them (the value is over the others). γ: angle between the view "
                "direction and the direction to the light (library's γ in brackets).\n\n",
                SCREEN_W, SCREEN_H, MAP);
    std::printf("| far | γ |");
    for (int c = 0; c < COLUMNS; ++c)
        std::printf(" %s |", COLUMN_NAMES[c]);
    std::printf(" default ≤ best of OGRE/OSG LiSPSM? | cascade ≤ OGRE PSSM(4)? |\n|---|---|");
    for (int c = 0; c < COLUMNS + 2; ++c)
        std::printf("---|");
    std::printf("\n");
    for (const Row& r : rows) {
        std::printf("| %g | %g° (%.1f°) |", r.far, r.gamma_deg, r.gamma_lib_deg);
        for (int c = 0; c < COLUMNS; ++c)
            std::printf(" %s |", cell(r.s[c]).c_str());
        const Sigma& mine = r.s[LIB_DEFAULT];
        double ogre = worst(r.s[OGRE_LISPSM], mine), osg = worst(r.s[OSG_LISPSM], mine);
        const Sigma& best = ogre <= osg ? r.s[OGRE_LISPSM] : r.s[OSG_LISPSM];
        std::printf(" %s | %s |\n", verdict(worst(mine, best), std::fmin(ogre, osg)).c_str(),
                    verdict(worst(r.s[LIB_CASCADE], r.s[OGRE_PSSM]),
                            worst(r.s[OGRE_PSSM], r.s[LIB_CASCADE])).c_str());
    }
#ifndef SWARP_HAVE_OSG
    std::printf("\nOSG column: OpenSceneGraph 3.6 (pkg-config openscenegraph-osgShadow) was not found "
                "at build time (Debian: apt-get install libopenscenegraph-dev).\n");
#endif
}


/* ---- the machinery checks (--check) ------------------------------------ */

int failures = 0;

void expect(bool ok, const std::string& what)
{
    if (!ok) {
        std::printf("FAIL: %s\n", what.c_str());
        ++failures;
    }
}

/* texel coordinates of p under a world -> light clip matrix */
void texel(const swarp_mat4& m, swarp_vec3 p, double* s, double* t)
{
    double x = m.m[0] * p.x + m.m[4] * p.y + m.m[8] * p.z + m.m[12];
    double y = m.m[1] * p.x + m.m[5] * p.y + m.m[9] * p.z + m.m[13];
    double w = m.m[3] * p.x + m.m[7] * p.y + m.m[11] * p.z + m.m[15];
    *s = (x / w + 1) / 2 * MAP;
    *t = (y / w + 1) / 2 * MAP;
}

/* screen pixel of p, from the camera's frame by hand (right +x, up +y,
 * forward -z: the scene's camera) */
void pixel(const swarp_camera& c, swarp_vec3 p, double* x, double* y)
{
    swarp_vec3 d = sub(p, c.eye);
    double z = -d.z, ty = std::tan(c.fovy / 2), tx = ty * c.aspect;
    *x = (d.x / (z * tx) + 1) / 2 * SCREEN_W;
    *y = (d.y / (z * ty) + 1) / 2 * SCREEN_H;
}

/* sigma of a ground point (normal +y) by central differences of the pixel
 * and texel positions along world x and z: D = J_scr J_tex^-1 does not
 * depend on the tangent basis, sigma = sqrt(largest eigenvalue of D^T D) */
double groundSigmaFD(const swarp_camera& c, const swarp_mat4& m, swarp_vec3 p)
{
    double h = 1e-4 * -sub(p, c.eye).z;
    double js[2][2], jt[2][2];
    for (int k = 0; k < 2; ++k) {
        swarp_vec3 e = k == 0 ? swarp_vec3{h, 0, 0} : swarp_vec3{0, 0, h};
        double x1, y1, x0, y0, s1, t1, s0, t0;
        pixel(c, add(p, e), &x1, &y1);
        pixel(c, sub(p, e), &x0, &y0);
        texel(m, add(p, e), &s1, &t1);
        texel(m, sub(p, e), &s0, &t0);
        js[0][k] = (x1 - x0) / (2 * h);
        js[1][k] = (y1 - y0) / (2 * h);
        jt[0][k] = (s1 - s0) / (2 * h);
        jt[1][k] = (t1 - t0) / (2 * h);
    }
    double det = jt[0][0] * jt[1][1] - jt[0][1] * jt[1][0];
    double inv[2][2] = {{jt[1][1] / det, -jt[0][1] / det}, {-jt[1][0] / det, jt[0][0] / det}};
    double d[2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            d[i][j] = js[i][0] * inv[0][j] + js[i][1] * inv[1][j];
    double a = d[0][0] * d[0][0] + d[1][0] * d[1][0], b = d[0][0] * d[0][1] + d[1][0] * d[1][1];
    double e = d[0][1] * d[0][1] + d[1][1] * d[1][1];
    return std::sqrt((a + e) / 2 + std::sqrt((a - e) * (a - e) / 4 + b * b));
}

/* Central differences with h = 1e-4 z: truncation ~ h^2 |f'''/f'| ~ 1e-8
 * relative (the maps vary on the scale of the depth z), rounding ~
 * 1e-16 |p| / h ~ 1e-10: 1e-6 leaves two orders of margin. */
const double CHECK_FD_REL = 1e-6;

void checkGroundSigma(const std::string& name, const swarp_camera& cam, const Maps& maps,
                      const Receivers& r)
{
    expect(maps.state == 0, name + ": matrix built");
    if (maps.state != 0)
        return;
    unsigned checked = 0;
    for (size_t k = 0; k < r.ground_p.size(); k += 37) {
        unsigned out = 0;
        std::vector<swarp_vec3> p(1, r.ground_p[k]), n(1, r.ground_n[k]);
        double lib = pointsSigma(cam, maps, p, n, &out);
        if (out)
            continue;
        /* the split by its own range: the first map whose [z_i, z_i+1]
         * holds the point's depth along the view direction */
        double depth = -sub(r.ground_p[k], cam.eye).z;
        unsigned i = 0;
        while (i + 1 < maps.count && !(maps.z[i] <= depth && depth <= maps.z[i + 1]))
            ++i;
        double fd = groundSigmaFD(cam, maps.m[i], r.ground_p[k]);
        ++checked;
        if (!(std::fabs(lib - fd) <= CHECK_FD_REL * fd)) {
            expect(false, name + ": ground sigma " + std::to_string(lib) + " = finite differences " +
                              std::to_string(fd));
            return;
        }
    }
    expect(checked >= 20, name + ": at least 20 ground points inside the map");
    std::printf("%s: ground sigma = finite differences at %u points (rel. %g)\n", name.c_str(),
                checked, CHECK_FD_REL);
}

/* OSG forms its light camera's position in float (osg::Vec3, BoundingSphere):
 * the axis of its view is off the light by at most a few 2^-24 rad, 1e-6 m
 * laterally over the 10 m moved here, below 1e-3 of the >= 1 mm texels a
 * 1024^2 map over a >= 100 m hull has. */
const double CHECK_ALONG_TEXELS = 1e-3;

void checkOsgAlongLight(swarp_vec3 light_dir, const Maps& maps, const Receivers& r, const std::string& tag)
{
    expect(maps.state == 0, tag + ": matrix finite");
    if (maps.state != 0)
        return;
    /* a direction across the light, in the plane of the light and world x */
    swarp_vec3 across = unit(sub(swarp_vec3{1, 0, 0}, scale(light_dir, light_dir.x)));
    double worst = 0, least_across = INFINITY;
    for (size_t k = 0; k < r.ground_p.size(); k += 23) {
        swarp_vec3 p = r.ground_p[k];
        double s0, t0, s1, t1, s2, t2;
        texel(maps.m[0], p, &s0, &t0);
        texel(maps.m[0], add(p, scale(light_dir, 10)), &s1, &t1);
        texel(maps.m[0], add(p, scale(across, 10)), &s2, &t2);
        worst = std::fmax(worst, std::hypot(s1 - s0, t1 - t0));
        least_across = std::fmin(least_across, std::hypot(s2 - s0, t2 - t0));
    }
    expect(worst <= CHECK_ALONG_TEXELS, tag + ": a point and the point 10 m along the light share a texel");
    expect(least_across > 1, tag + ": 10 m across the light moves more than a texel");
    std::printf("%s: 10 m along the light moves at most %.2e texel, 10 m across at least %.3g texels\n",
                tag.c_str(), worst, least_across);
}

int runChecks()
{
    Scene sc;
    auto focused = std::make_shared<Ogre::FocusedShadowCameraSetup>();
    auto pssm = std::make_shared<Ogre::PSSMShadowCameraSetup>();
    Frame f = {sc.sm, sc.cam, sc.vp, sc.light};
    for (double g : {60.0, 30.0, 150.0, 20.0, 5.0}) {
        swarp_camera cam = makeCamera(200);
        sc.cam->setFarClipDistance(200);
        sc.sm->setShadowFarDistance(200);
        swarp_vec3 dir = sc.setLight(g);
        double adj_near = Z_NEAR, adj_far = 200;
        expect(swarp_body_adjusted_range(&cam, &BOX, &adj_near, &adj_far) == SWARP_OK, "adjusted range");
        swarp_light light = swarp_light();
        light.direction = dir;
        Receivers rec = makeReceivers(cam, unit(scale(dir, -1)), adj_near, adj_far);
        char tag[32];
        std::snprintf(tag, sizeof tag, " gamma %g", g);
#ifdef SWARP_HAVE_OSG
        Maps osg = osgMaps(cam, dir, adj_near, adj_far);
        checkOsgAlongLight(dir, osg, rec, std::string("OSG LiSPSM") + tag);
        checkGroundSigma(std::string("OSG LiSPSM") + tag, cam, osg, rec);
#endif
        std::vector<double> whole = {adj_near, adj_far};
        checkGroundSigma(std::string("OGRE focused") + tag, cam, ogreMaps(f, focused, 1, whole), rec);
        checkGroundSigma(std::string("swarp default") + tag, cam,
                         libSingle(cam, light, libOptions(), adj_near, adj_far), rec);
        checkGroundSigma(std::string("swarp cascade") + tag, cam, libCascade(cam, light), rec);
        pssm->calculateSplitPoints(SPLITS, Ogre::Real(Z_NEAR), 200);
        const Ogre::PSSMShadowCameraSetup::SplitPointList& op = pssm->getSplitPoints();
        checkGroundSigma(std::string("OGRE PSSM(4)") + tag, cam,
                         ogreMaps(f, pssm, SPLITS, std::vector<double>(op.begin(), op.end())), rec);
    }
#ifndef SWARP_HAVE_OSG
    std::printf("OSG checks skipped: OpenSceneGraph 3.6 not found at build time\n");
#endif
    if (failures)
        std::printf("%d failure(s)\n", failures);
    return failures ? 1 : 0;
}

} // namespace

int main(int argc, char** argv)
{
    const char* commit = "(unknown)";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--check"))
            return runChecks();
        if (!std::strcmp(argv[i], "--commit") && i + 1 < argc)
            commit = argv[++i];
    }
    std::vector<Row> rows;
    {
        Scene sc;
        auto focused = std::make_shared<Ogre::FocusedShadowCameraSetup>();
        auto lispsm = std::make_shared<Ogre::LiSPSMShadowCameraSetup>();
        auto pssm = std::make_shared<Ogre::PSSMShadowCameraSetup>();
        Ogre::ShadowCameraSetupPtr setups[3] = {focused, lispsm, pssm};
        for (double z_far : FARS)
            for (double g : GAMMAS_DEG)
                rows.push_back(evaluate(sc, z_far, g, setups, pssm.get()));
    }
    printTable(rows, commit);
    return 0;
}
