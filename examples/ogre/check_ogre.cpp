/* The OGRE adapter driven through OGRE 1.12's shadow camera path, headless
 * (headless.h): for light directions including the exact overhead light and
 * light parallel and antiparallel to the view,
 *   - OGRE's camera matrices equal the view and projection built by hand from
 *     the library camera the adapter reads (the conventions: full vertical
 *     field of view, aspect, up, near/far);
 *   - the texture camera OGRE ends up with gives the library's matrix,
 *     computed here from the scene's own description, to the rounding of
 *     float matrices; split by split for the PSSM-style setup, with the same
 *     split distances;
 *   - its matrices are finite, also where OGRE's own LiSPSM's are not (or
 *     where OGRE aborts);
 * and prints the measured error (swarp_measure_max: sigma over H with
 * bisector receivers, docs/accuracy.md) of OGRE's built-in setups and of the
 * adapter side by side, at the same map and screen resolution. */
#include "headless.h"
#include "ogre_scene.h"
#include "swarp_ogre.h"

#include <OgreShadowCameraSetupFocused.h>
#include <OgreShadowCameraSetupLiSPSM.h>
#include <OgreShadowCameraSetupPSSM.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

using swarp_ogre_test::HeadlessRoot;
using swarp_ogre_test::HeadlessSceneManager;
using swarp_ogre_test::SizedTarget;

using namespace swarp_ogre_test;

namespace {

/* The scene, every number exact in float so that OGRE holds exactly what the
 * library is given: eye 3 above the ground looking along -z (identity
 * orientation), fovy 1 rad, aspect 2 (a 1920 x 960 screen), near 0.5, far
 * 150 (also the shadow far distance), 1024^2 maps, 3 splits. */
const double EYE_Y = 3, EYE_Z = 10, FOVY = 1.0, ASPECT = 2.0, Z_NEAR = 0.5, Z_FAR = 150;
const unsigned SCREEN_W = 1920, SCREEN_H = 960, MAP = 1024, SPLITS = 3;
/* a ground slab and a tower on it; S is their union */
const swarp_aabb GROUND = {{-60, -1, -160}, {60, 0, 20}};
const swarp_aabb TOWER = {{-2, 0, -32}, {2, 10, -28}};
const swarp_aabb SCENE = {{-60, -1, -160}, {60, 10, 20}};

/* gamma_n = n u / (1 - n u), u = FLT_EPSILON / 2: the rounding bound of an
 * n-term float dot product (Higham, Accuracy and Stability, (3.4)).  A float
 * product of rounded 4x4 matrices has 4-term dot products of entries each
 * rounded once (2 roundings) and summed in float (4): gamma_6; one more for
 * the double products the library and this check form. */
const double SW_CHECK_GAMMA_7 = 7 * (FLT_EPSILON / 2) / (1 - 7 * (FLT_EPSILON / 2));

int failures = 0;

void check(bool ok, const std::string& what)
{
    if (!ok) {
        std::printf("FAIL: %s\n", what.c_str());
        ++failures;
    }
}

struct Light {
    const char* name;
    Ogre::Quaternion orientation; /* exact quaternions: exact directions */
    Ogre::Vector3 direction;      /* used when orientation is not given */
    bool exact;
    Ogre::Vector3 expect;         /* the exact direction, when exact */
};

/* every element of got within gamma_7 sum_k |P_ik||V_kj| of want */
bool matchesProduct(const Ogre::Matrix4& P, const Ogre::Matrix4& V, const Ogre::Matrix4& got,
                    const swarp_mat4& want, double* worst)
{
    bool ok = true;
    *worst = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            double scale = 0;
            for (int k = 0; k < 4; ++k)
                scale += std::fabs(double(P[r][k])) * std::fabs(double(V[k][c]));
            double err = std::fabs(double(got[r][c]) - want.m[c * 4 + r]);
            double bound = SW_CHECK_GAMMA_7 * scale;
            if (err > bound)
                ok = false;
            if (bound > 0 && err / bound > *worst)
                *worst = err / bound;
        }
    return ok;
}

/* OpenGL's lookAt and perspective for the library camera, by hand */
Ogre::Matrix4 handViewProj(const swarp_camera& c)
{
    Ogre::Vector3 f(c.dir.x, c.dir.y, c.dir.z), u(c.up.x, c.up.y, c.up.z);
    Ogre::Vector3 e(c.eye.x, c.eye.y, c.eye.z);
    f.normalise();
    Ogre::Vector3 s = f.crossProduct(u);
    s.normalise();
    Ogre::Vector3 t = s.crossProduct(f);
    Ogre::Matrix4 V(s.x, s.y, s.z, -s.dotProduct(e), t.x, t.y, t.z, -t.dotProduct(e),
                    -f.x, -f.y, -f.z, f.dotProduct(e), 0, 0, 0, 1);
    double g = 1 / std::tan(c.fovy / 2), n = c.z_near, fa = c.z_far;
    Ogre::Matrix4 P(g / c.aspect, 0, 0, 0, 0, g, 0, 0, 0, 0, (fa + n) / (n - fa),
                    2 * fa * n / (n - fa), 0, 0, -1, 0);
    return P * V;
}

swarp_camera referenceCamera()
{
    swarp_camera c = swarp_camera();
    c.eye = {0, EYE_Y, EYE_Z};
    c.dir = {0, 0, -1};
    c.up = {0, 1, 0};
    c.fovy = FOVY;
    c.aspect = ASPECT;
    c.z_near = Z_NEAR;
    c.z_far = Z_FAR;
    return c;
}

swarp_measure_res resolution()
{
    swarp_measure_res r = {SCREEN_W, SCREEN_H, MAP, MAP};
    return r;
}

/* sigma over H between z0 and z1 (clipped to the adjusted range); -1 when
 * that range is empty, NaN when the matrix is not finite */
double measure(const swarp_camera& cam, const swarp_light& light, const Ogre::Matrix4& m,
               double z0, double z1, double adj_near, double adj_far, unsigned* outside)
{
    z0 = std::fmax(z0, adj_near);
    z1 = std::fmin(z1, adj_far);
    if (!(z0 < z1))
        return -1;
    if (!matFinite(m))
        return NAN;
    swarp_mat4 mm = matFromOgre(m);
    swarp_measure_res res = resolution();
    swarp_measured_error e;
    swarp_status st = swarp_measure_max(&cam, z0, z1, &light, &SCENE, &mm, &res, nullptr, &e);
    if (swarp_status_is_error(st))
        return -1;
    *outside += e.outside;
    return e.max_sigma;
}

struct Frame {
    HeadlessSceneManager* sm;
    Ogre::Camera* cam;
    Ogre::Viewport* vp;
    Ogre::Light* light;
};

/* two frames: the first leaves the visible bounds OGRE's focused setups read
 * in the second, as in a running engine */
void run(Frame& f, const Ogre::ShadowCameraSetupPtr& setup, size_t textures)
{
    f.sm->resetShadowCameras();
    f.sm->setShadowTextureCountPerLightType(Ogre::Light::LT_DIRECTIONAL, textures);
    f.light->setCustomShadowCameraSetup(setup);
    f.sm->renderShadows(f.cam, f.vp);
    f.sm->renderShadows(f.cam, f.vp);
}

std::string cell(double sigma, unsigned outside)
{
    char b[64];
    if (std::isnan(sigma))
        std::snprintf(b, sizeof b, "non-finite");
    else if (sigma < 0)
        std::snprintf(b, sizeof b, "-");
    else if (outside)
        std::snprintf(b, sizeof b, "%.3g (%u out)", sigma, outside);
    else
        std::snprintf(b, sizeof b, "%.3g", sigma);
    return b;
}

/* One of OGRE's own setups, measured: sigma (max over its maps, each over
 * its own depth range), outside count, whether its matrices were finite,
 * and whether OGRE aborted.  OGRE 1.12's focused setups abort the process
 * in some configurations (an assertion on a NaN box in
 * FocusedShadowCameraSetup::transformToUnitCube), so each runs in a child
 * process. */
struct OgreRun {
    double sigma;
    unsigned outside;
    int finite;
    int aborted;
};

OgreRun runOgre(Frame& f, const Ogre::ShadowCameraSetupPtr& setup, size_t textures,
                const std::vector<double>& ranges, const swarp_camera& cam,
                const swarp_light& light, double adj_near, double adj_far)
{
    OgreRun r = {-1, 0, 1, 0};
    int fds[2];
    if (pipe(fds) != 0)
        return r;
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, 2);
        run(f, setup, textures);
        for (size_t i = 0; i < textures; ++i) {
            Ogre::Matrix4 m = shadowViewProj(f.sm, i);
            if (!matFinite(m))
                r.finite = 0;
            double s = measure(cam, light, m, ranges[i], ranges[i + 1], adj_near, adj_far, &r.outside);
            r.sigma = (std::isnan(s) || std::isnan(r.sigma)) ? NAN : std::fmax(r.sigma, s);
        }
        ssize_t w = write(fds[1], &r, sizeof r);
        _exit(w == ssize_t(sizeof r) ? 0 : 1);
    }
    close(fds[1]);
    OgreRun got;
    ssize_t n = read(fds[0], &got, sizeof got);
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (n == ssize_t(sizeof got) && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0)
        return got;
    r.aborted = 1;
    r.finite = 0;
    r.sigma = NAN;
    return r;
}

std::string cell(const OgreRun& r)
{
    return r.aborted ? "aborts" : cell(r.sigma, r.outside);
}

} // namespace

int main()
{
    HeadlessRoot root;
    HeadlessSceneManager* sm = new HeadlessSceneManager("check");
    sm->setShadowTechnique(Ogre::SHADOWTYPE_TEXTURE_MODULATIVE);
    sm->setShadowFarDistance(Ogre::Real(Z_FAR));
    sm->createShadowCameras(SPLITS, MAP);
    addBoxObject(sm, "ground", GROUND);
    addBoxObject(sm, "tower", TOWER);

    Ogre::Camera* cam = sm->createCamera("main");
    Ogre::SceneNode* camNode = sm->getRootSceneNode()->createChildSceneNode();
    camNode->attachObject(cam);
    camNode->setPosition(0, Ogre::Real(EYE_Y), Ogre::Real(EYE_Z));
    cam->setFOVy(Ogre::Radian(Ogre::Real(FOVY)));
    cam->setAspectRatio(Ogre::Real(ASPECT));
    cam->setNearClipDistance(Ogre::Real(Z_NEAR));
    cam->setFarClipDistance(Ogre::Real(Z_FAR));
    SizedTarget window("window", SCREEN_W, SCREEN_H);
    Ogre::Viewport* vp = window.addViewport(cam);

    Ogre::Light* light = sm->createLight("sun");
    light->setType(Ogre::Light::LT_DIRECTIONAL);
    Ogre::SceneNode* lightNode = sm->getRootSceneNode()->createChildSceneNode();
    lightNode->attachObject(light);
    Frame frame = {sm, cam, vp, light};

    swarp_camera ref_cam = referenceCamera();
    swarp_camera adapter_cam;
    check(swarp_ogre::cameraFromOgre(*cam, *light, &adapter_cam) == SWARP_OK, "cameraFromOgre");
    {
        /* the conventions: OGRE's camera against lookAt/perspective by hand */
        Ogre::Matrix4 ogre = cam->getProjectionMatrix() * Ogre::Matrix4(cam->getViewMatrix());
        double worst;
        check(matchesProduct(cam->getProjectionMatrix(), Ogre::Matrix4(cam->getViewMatrix()), ogre,
                             matFromOgre(handViewProj(adapter_cam)), &worst),
              "OGRE's camera = lookAt/perspective of the library camera");
        /* == on the fields: -0 == 0 (OGRE's derived direction has signed zeros) */
        auto same = [](const swarp_vec3& a, const swarp_vec3& b) {
            return a.x == b.x && a.y == b.y && a.z == b.z;
        };
        check(same(adapter_cam.eye, ref_cam.eye) && same(adapter_cam.dir, ref_cam.dir) &&
                  same(adapter_cam.up, ref_cam.up) && adapter_cam.fovy == ref_cam.fovy &&
                  adapter_cam.aspect == ref_cam.aspect && adapter_cam.z_near == ref_cam.z_near &&
                  adapter_cam.z_far == ref_cam.z_far,
              "the library camera read from OGRE is the scene's camera");
    }
    double adj_near, adj_far;
    check(swarp_body_adjusted_range(&ref_cam, &SCENE, &adj_near, &adj_far) == SWARP_OK,
          "adjusted range");

    /* (0.5, -0.5, -0.5, -0.5) turns -z into -y, (0, 0, 1, 0) into +z; both in
     * float arithmetic exactly */
    const Light lights[] = {
        {"overhead (exact)", Ogre::Quaternion(0.5f, -0.5f, -0.5f, -0.5f), {}, true, {0, -1, 0}},
        {"parallel to view (exact)", Ogre::Quaternion::IDENTITY, {}, true, {0, 0, -1}},
        {"antiparallel (exact)", Ogre::Quaternion(0, 0, 1, 0), {}, true, {0, 0, 1}},
        {"oblique (1,-2,-1)", Ogre::Quaternion::ZERO, {1, -2, -1}, false, {}},
        {"low side (1,-0.3,0.2)", Ogre::Quaternion::ZERO, {1, -0.3f, 0.2f}, false, {}},
        {"behind (0.2,-1,-0.6)", Ogre::Quaternion::ZERO, {0.2f, -1, -0.6f}, false, {}},
        {"facing (-0.3,-1,0.7)", Ogre::Quaternion::ZERO, {-0.3f, -1, 0.7f}, false, {}},
        {"grazing parallel (0,-0.02,-1)", Ogre::Quaternion::ZERO, {0, -0.02f, -1}, false, {}},
    };

    auto ogreDefault = std::make_shared<Ogre::DefaultShadowCameraSetup>();
    auto ogreFocused = std::make_shared<Ogre::FocusedShadowCameraSetup>();
    auto ogreLispsm = std::make_shared<Ogre::LiSPSMShadowCameraSetup>();
    auto ogrePssm = std::make_shared<Ogre::PSSMShadowCameraSetup>();
    ogrePssm->calculateSplitPoints(SPLITS, Ogre::Real(Z_NEAR), Ogre::Real(Z_FAR));
    auto single = std::make_shared<swarp_ogre::ShadowCameraSetup>();
    swarp_cascade_options copt = swarp_cascade_options();
    copt.split.count = SPLITS;
    auto pssm = std::make_shared<swarp_ogre::PSSMShadowCameraSetup>(copt);

    std::printf("sigma over H (bisector receivers), %ux%u screen, %u^2 maps, %u splits; "
                "\"n out\": samples of H outside the float map (on a tight fit, boundary samples round out)\n", SCREEN_W, SCREEN_H, MAP, SPLITS);
    std::printf("%-30s %-16s %-16s %-16s %-16s | %-12s %-12s\n", "light", "OGRE default",
                "OGRE focused", "OGRE LiSPSM", "OGRE PSSM", "swarp", "swarp PSSM");
    int ogre_nonfinite = 0;
    for (const Light& L : lights) {
        if (L.orientation == Ogre::Quaternion::ZERO) {
            lightNode->setOrientation(Ogre::Quaternion::IDENTITY);
            lightNode->setDirection(L.direction.normalisedCopy(), Ogre::Node::TS_WORLD);
        } else {
            lightNode->setOrientation(L.orientation);
        }
        lightNode->_update(true, false);
        if (L.exact)
            check(light->getDerivedDirection() == L.expect, std::string(L.name) + ": exact direction");
        swarp_light ref_light = swarp_light();
        ref_light.type = SWARP_LIGHT_DIRECTIONAL;
        Ogre::Vector3 d = light->getDerivedDirection();
        ref_light.direction = {d.x, d.y, d.z};
        std::string tag = L.name;

        /* OGRE's own setups */
        std::vector<double> whole = {adj_near, adj_far};
        const Ogre::PSSMShadowCameraSetup::SplitPointList& op = ogrePssm->getSplitPoints();
        std::vector<double> ogre_splits(op.begin(), op.end());
        OgreRun r_def = runOgre(frame, ogreDefault, 1, whole, ref_cam, ref_light, adj_near, adj_far);
        OgreRun r_foc = runOgre(frame, ogreFocused, 1, whole, ref_cam, ref_light, adj_near, adj_far);
        OgreRun r_lis = runOgre(frame, ogreLispsm, 1, whole, ref_cam, ref_light, adj_near, adj_far);
        OgreRun r_pssm = runOgre(frame, ogrePssm, SPLITS, ogre_splits, ref_cam, ref_light, adj_near,
                                 adj_far);
        ogre_nonfinite += !r_lis.finite;

        /* the adapter, one map: the library's matrix for the scene */
        swarp_setup_options o = swarp_setup_options();
        o.depth_range = SWARP_DEPTH_NEG_ONE_TO_ONE;
        o.map_width = o.map_height = MAP;
        o.screen_width = SCREEN_W;
        o.screen_height = SCREEN_H;
        swarp_setup_result want;
        swarp_status st = swarp_setup(&ref_cam, &ref_light, &SCENE, &o, &want, nullptr, 0, nullptr);
        check(!swarp_status_is_error(st), tag + ": swarp_setup");
        run(frame, single, 1);
        check(single->lastStatus() == st, tag + ": the adapter's status is the library's");
        swarp_ogre_test::ProbeCamera* tc = sm->shadowCamera(0);
        Ogre::Matrix4 got = shadowViewProj(sm, 0);
        double worst;
        check(matFinite(got), tag + ": adapter matrix finite");
        check(matchesProduct(tc->getProjectionMatrix(), Ogre::Matrix4(tc->getViewMatrix()), got,
                             want.matrix, &worst),
              tag + ": texture camera = library matrix (float rounding)");
        unsigned out_single = 0;
        double s_single = measure(ref_cam, ref_light, got, adj_near, adj_far, adj_near, adj_far,
                                  &out_single);

        /* the adapter, splits */
        swarp_cascade_options co = copt;
        co.setup = o;
        swarp_cascade_result cres;
        swarp_cascade_split csplits[SWARP_CASCADE_MAX_SPLITS];
        size_t count = 0;
        st = swarp_cascade_setup(&ref_cam, &ref_light, &SCENE, &co, &cres, csplits,
                                 SWARP_CASCADE_MAX_SPLITS, &count);
        check(!swarp_status_is_error(st) && count == SPLITS, tag + ": swarp_cascade_setup");
        run(frame, pssm, SPLITS);
        unsigned out_cascade = 0;
        double s_cascade = -1;
        for (unsigned i = 0; i < SPLITS && i < count; ++i) {
            swarp_ogre_test::ProbeCamera* sc = sm->shadowCamera(i);
            Ogre::Matrix4 g = shadowViewProj(sm, i);
            check(matFinite(g), tag + ": adapter split matrix finite");
            check(matchesProduct(sc->getProjectionMatrix(), Ogre::Matrix4(sc->getViewMatrix()), g,
                                 csplits[i].matrix, &worst),
                  tag + ": split " + std::to_string(i) + " texture camera = library matrix");
            unsigned out_split = 0;
            s_cascade = std::fmax(s_cascade, measure(ref_cam, ref_light, g, csplits[i].z_near,
                                                     csplits[i].z_far, adj_near, adj_far, &out_split));
            out_cascade += out_split;
        }
        const std::vector<Ogre::Real>& sp = pssm->getSplitPoints();
        check(sp.size() == count + 1, tag + ": split point count");
        for (size_t i = 0; i < sp.size() && i <= count; ++i)
            check(sp[i] == Ogre::Real(cres.splits[i]), tag + ": split point " + std::to_string(i));

        std::printf("%-30s %-16s %-16s %-16s %-16s | %-12s %-12s\n", L.name,
                    cell(r_def).c_str(), cell(r_foc).c_str(), cell(r_lis).c_str(),
                    cell(r_pssm).c_str(),
                    cell(s_single, out_single).c_str(), cell(s_cascade, out_cascade).c_str());
    }
    std::printf("OGRE's LiSPSM non-finite or aborting in %d of %zu cases; the adapter finite in all\n",
                ogre_nonfinite, sizeof lights / sizeof lights[0]);
    light->setCustomShadowCameraSetup(Ogre::ShadowCameraSetupPtr());
    delete sm;
    if (failures)
        std::printf("%d failure(s)\n", failures);
    return failures ? 1 : 0;
}
