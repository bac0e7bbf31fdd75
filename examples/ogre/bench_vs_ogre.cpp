/* vs-ogre: the cost of this library's default setups against OGRE 1.12's
 * shadow camera setups on the same camera, light and scene box.
 *
 *   single map   swarp_setup with zeroed options (LiSPSM, warp strength by
 *                measurement, the measured error reported) against
 *                LiSPSMShadowCameraSetup::getShadowCamera;
 *   4 splits     swarp_cascade_setup with zeroed options but 4 splits
 *                (split positions by measurement, every split measured)
 *                against PSSMShadowCameraSetup::getShadowCamera for its 4
 *                textures (OGRE's split points are computed once, outside
 *                the loop, as OGRE does it).
 *
 * Scene as compare_engines.cpp: a 200 x 30 x 200 m box, the eye 2 m above
 * it looking along -z, fovy 60 deg, 1024 x 768 screen, 1024^2 maps, far 200;
 * the light at gamma (from the view direction) 30, 60 and 150 degrees.
 * OGRE's focused setups read the scene manager's visible bounds, which one
 * headless shadow pass (renderShadows) fills before timing.
 *
 * Each rep times one OGRE call (or four) and one library call, interleaved,
 * so both see the same machine state; medians over REPS reps.  The ratio
 * OGRE / library is printed per row; more than 1 means the library is
 * faster.
 *
 *   vs-ogre [--reps N]          (meson benchmark 'vs-ogre') */
#include "headless.h"
#include "ogre_scene.h"

#include <OgreShadowCameraSetupLiSPSM.h>
#include <OgreShadowCameraSetupPSSM.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <vector>

using swarp_ogre_test::HeadlessRoot;
using swarp_ogre_test::HeadlessSceneManager;
using swarp_ogre_test::SizedTarget;

namespace {

const double PI = 3.14159265358979323846;
const double EYE_Y = 2, FOVY_DEG = 60, Z_NEAR = 0.5, Z_FAR = 200;
const unsigned SCREEN_W = 1024, SCREEN_H = 768, MAP = 1024, SPLITS = 4;
const swarp_aabb BOX = {{-100, -30, -100}, {100, 0, 100}};
const double GAMMAS_DEG[] = {30, 60, 150};
/* at least 1000 reps (the median of fewer moves by several per cent from
 * run to run on a shared 2-core machine) */
const int DEFAULT_REPS = 1000;

double nowNs()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

swarp_camera makeCamera()
{
    swarp_camera c = swarp_camera();
    c.eye = {0, EYE_Y, 0};
    c.dir = {0, 0, -1};
    c.up = {0, 1, 0};
    c.fovy = FOVY_DEG * PI / 180;
    c.aspect = double(SCREEN_W) / SCREEN_H;
    c.z_near = Z_NEAR;
    c.z_far = Z_FAR;
    return c;
}

swarp_setup_options libOptions()
{
    swarp_setup_options o = swarp_setup_options();
    o.map_width = o.map_height = MAP;
    o.screen_width = SCREEN_W;
    o.screen_height = SCREEN_H;
    return o;
}

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
        sm = new HeadlessSceneManager("bench");
        sm->setShadowTechnique(Ogre::SHADOWTYPE_TEXTURE_MODULATIVE);
        sm->createShadowCameras(SPLITS, MAP);
        swarp_ogre_test::addBoxObject(sm, "box", BOX);
        cam = sm->createCamera("main");
        Ogre::SceneNode* camNode = sm->getRootSceneNode()->createChildSceneNode();
        camNode->attachObject(cam);
        camNode->setPosition(0, Ogre::Real(EYE_Y), 0);
        cam->setFOVy(Ogre::Degree(Ogre::Real(FOVY_DEG)));
        cam->setAspectRatio(Ogre::Real(double(SCREEN_W) / SCREEN_H));
        cam->setNearClipDistance(Ogre::Real(Z_NEAR));
        cam->setFarClipDistance(Ogre::Real(Z_FAR));
        sm->setShadowFarDistance(Ogre::Real(Z_FAR));
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
    swarp_vec3 setLight(double gamma_deg)
    {
        const double g = gamma_deg * PI / 180;
        lightNode->setOrientation(Ogre::Quaternion::IDENTITY);
        lightNode->setDirection(Ogre::Vector3(0, Ogre::Real(-std::sin(g)), Ogre::Real(std::cos(g))),
                                Ogre::Node::TS_WORLD);
        lightNode->_update(true, false);
        Ogre::Vector3 d = light->getDerivedDirection();
        return {d.x, d.y, d.z};
    }
    /* one headless shadow pass with setup: the bounds OGRE's setups read */
    void prepare(const Ogre::ShadowCameraSetupPtr& setup, unsigned textures)
    {
        sm->resetShadowCameras();
        sm->setShadowTextureCountPerLightType(Ogre::Light::LT_DIRECTIONAL, textures);
        light->setCustomShadowCameraSetup(setup);
        sm->renderShadows(cam, vp);
        sm->renderShadows(cam, vp);
    }
};

struct Timing {
    double ogre_ns, lib_ns;
    int lib_errors;
};

/* OGRE's single-map LiSPSM against swarp_setup's default */
Timing timeSingle(Scene& sc, const Ogre::ShadowCameraSetupPtr& lispsm, const swarp_light& light, int reps)
{
    sc.prepare(lispsm, 1);
    const swarp_camera cam = makeCamera();
    const swarp_setup_options o = libOptions();
    std::vector<double> t_ogre(reps), t_lib(reps);
    Timing t = Timing();
    for (int i = 0; i < reps; ++i) {
        double t0 = nowNs();
        lispsm->getShadowCamera(sc.sm, sc.cam, sc.vp, sc.light, sc.sm->shadowCamera(0), 0);
        double t1 = nowNs();
        swarp_setup_result res;
        swarp_status st = swarp_setup(&cam, &light, &BOX, &o, &res, nullptr, 0, nullptr);
        double t2 = nowNs();
        t.lib_errors += swarp_status_is_error(st);
        t_ogre[i] = t1 - t0;
        t_lib[i] = t2 - t1;
    }
    t.ogre_ns = median(t_ogre);
    t.lib_ns = median(t_lib);
    return t;
}

/* OGRE's PSSM(4) against swarp_cascade_setup's default with 4 splits */
Timing timeCascade(Scene& sc, const std::shared_ptr<Ogre::PSSMShadowCameraSetup>& pssm,
                   const swarp_light& light, int reps)
{
    pssm->calculateSplitPoints(SPLITS, Ogre::Real(Z_NEAR), Ogre::Real(Z_FAR));
    sc.prepare(pssm, SPLITS);
    const swarp_camera cam = makeCamera();
    swarp_cascade_options co = swarp_cascade_options();
    co.setup = libOptions();
    co.split.count = SPLITS;
    std::vector<double> t_ogre(reps), t_lib(reps);
    Timing t = Timing();
    for (int i = 0; i < reps; ++i) {
        double t0 = nowNs();
        for (unsigned j = 0; j < SPLITS; ++j)
            pssm->getShadowCamera(sc.sm, sc.cam, sc.vp, sc.light, sc.sm->shadowCamera(j), j);
        double t1 = nowNs();
        swarp_cascade_result cres;
        swarp_cascade_split sp[SWARP_CASCADE_MAX_SPLITS];
        size_t count = 0;
        swarp_status st = swarp_cascade_setup(&cam, &light, &BOX, &co, &cres, sp, SWARP_CASCADE_MAX_SPLITS, &count);
        double t2 = nowNs();
        t.lib_errors += swarp_status_is_error(st) || count != SPLITS;
        t_ogre[i] = t1 - t0;
        t_lib[i] = t2 - t1;
    }
    t.ogre_ns = median(t_ogre);
    t.lib_ns = median(t_lib);
    return t;
}

} // namespace

int main(int argc, char** argv)
{
    int reps = DEFAULT_REPS;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--reps") && i + 1 < argc)
            reps = std::max(1, std::atoi(argv[++i]));
    Scene sc;
    auto lispsm = std::make_shared<Ogre::LiSPSMShadowCameraSetup>();
    auto pssm = std::make_shared<Ogre::PSSMShadowCameraSetup>();
    std::printf("medians over %d interleaved reps, ns per call (OGRE PSSM: its 4 getShadowCamera calls)\n\n", reps);
    std::printf("| setup | γ (deg) | OGRE 1.12 | libshadowwarp default | OGRE / library |\n");
    std::printf("|---|---|---|---|---|\n");
    int errors = 0;
    for (double g : GAMMAS_DEG) {
        swarp_light light = swarp_light();
        light.type = SWARP_LIGHT_DIRECTIONAL;
        light.direction = sc.setLight(g);
        Timing s = timeSingle(sc, lispsm, light, reps);
        std::printf("| LiSPSM vs swarp_setup | %g | %.0f | %.0f | %.2f |\n", g, s.ogre_ns, s.lib_ns,
                    s.ogre_ns / s.lib_ns);
        Timing c = timeCascade(sc, pssm, light, reps);
        std::printf("| PSSM(4) vs swarp_cascade_setup(4) | %g | %.0f | %.0f | %.2f |\n", g, c.ogre_ns,
                    c.lib_ns, c.ogre_ns / c.lib_ns);
        errors += s.lib_errors + c.lib_errors;
    }
    std::printf("\n(clock_gettime overhead, about 20-40 ns, is included in every sample)\n");
    if (errors)
        std::printf("%d library calls returned an error\n", errors);
    return errors ? 1 : 0;
}
