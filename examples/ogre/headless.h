/* A headless OGRE 1.12 frame for the adapter's check: no render window, no
 * plugins, no GPU.
 *
 * OGRE's SceneManager::prepareShadowTextures cannot run without a real
 * render system: ensureShadowTexturesCreated needs textures with render
 * targets, initShadowVolumeMaterials asserts a RenderSystem, and
 * shadowRTT->update() renders.  What the shadow camera ends up with,
 * however, is decided by one call in its loop,
 * ShadowCameraSetup::getShadowCamera(sm, cam, vp, light, texCam, j), and
 * by the bounds the scene manager keeps per camera
 * (getVisibleObjectsBoundsInfo), which OGRE's focused setups read.
 * HeadlessSceneManager::renderShadows runs that loop as OGRE 1.12.10 writes
 * it (OgreShadowRenderer.cpp, prepareShadowTextures and
 * ensureShadowTexturesCreated), with OGRE's own cameras, scene nodes,
 * lights, viewports and visibility pass, and stands in only for the
 * texture and the draw calls. */
#ifndef SWARP_OGRE_HEADLESS_H
#define SWARP_OGRE_HEADLESS_H

#include <Ogre.h>
#include <OgreDefaultHardwareBufferManager.h>

#include <memory>
#include <vector>

namespace swarp_ogre_test {

/* A render system that draws nothing.  OGRE's Viewport asks the active
 * render system for its material scheme and Frustum for its projection
 * convention; everything else is never called on this path. */
class NullRenderSystem : public Ogre::RenderSystem {
public:
    NullRenderSystem();
    ~NullRenderSystem() override;
    const Ogre::String& getName(void) const override;
    void setConfigOption(const Ogre::String&, const Ogre::String&) override {}
    Ogre::HardwareOcclusionQuery* createHardwareOcclusionQuery(void) override { return nullptr; }
    Ogre::String validateConfigOptions(void) override { return Ogre::BLANKSTRING; }
    Ogre::RenderSystemCapabilities* createRenderSystemCapabilities() const override;
    Ogre::MultiRenderTarget* createMultiRenderTarget(const Ogre::String&) override { return nullptr; }
    void _setSampler(size_t, Ogre::Sampler&) override {}
    void _setTexture(size_t, bool, const Ogre::TexturePtr&) override {}
    void setColourBlendState(const Ogre::ColourBlendState&) override {}
    void _setAlphaRejectSettings(Ogre::CompareFunction, unsigned char, bool) override {}
    Ogre::DepthBuffer* _createDepthBufferFor(Ogre::RenderTarget*) override { return nullptr; }
    void _endFrame(void) override {}
    void _setViewport(Ogre::Viewport*) override {}
    void _setCullingMode(Ogre::CullingMode) override {}
    void _setDepthBufferParams(bool, bool, Ogre::CompareFunction) override {}
    void _setDepthBias(float, float) override {}
    /* OpenGL's convention, [-1, 1] clip depth: the matrix is used as given */
    void _convertProjectionMatrix(const Ogre::Matrix4& m, Ogre::Matrix4& dest, bool) override { dest = m; }
    void _setPolygonMode(Ogre::PolygonMode) override {}
    void setStencilCheckEnabled(bool) override {}
    void setStencilBufferParams(Ogre::CompareFunction, Ogre::uint32, Ogre::uint32, Ogre::uint32,
                                Ogre::StencilOperation, Ogre::StencilOperation,
                                Ogre::StencilOperation, bool, bool) override {}
    void bindGpuProgramParameters(Ogre::GpuProgramType, const Ogre::GpuProgramParametersPtr&,
                                  Ogre::uint16) override {}
    void setScissorTest(bool, const Ogre::Rect&) override {}
    void clearFrameBuffer(unsigned int, const Ogre::ColourValue&, Ogre::Real, unsigned short) override {}
    Ogre::Real getHorizontalTexelOffset(void) override { return 0; }
    Ogre::Real getVerticalTexelOffset(void) override { return 0; }
    Ogre::Real getMinimumDepthInputValue(void) override { return -1; }
    Ogre::Real getMaximumDepthInputValue(void) override { return 1; }
    void _setRenderTarget(Ogre::RenderTarget*) override {}
    void beginProfileEvent(const Ogre::String&) override {}
    void endProfileEvent(void) override {}
    void markProfileEvent(const Ogre::String&) override {}
    void initialiseFromRenderSystemCapabilities(Ogre::RenderSystemCapabilities*,
                                                Ogre::RenderTarget*) override {}
};

/* The render target of a window or of a shadow texture: only its size. */
class SizedTarget : public Ogre::RenderTarget {
public:
    SizedTarget(const Ogre::String& name, unsigned width, unsigned height);
    void copyContentsToMemory(const Ogre::Box&, const Ogre::PixelBox&, FrameBuffer) override {}
    bool requiresTextureFlipping() const override { return false; }
};

/* A texture camera that also shows the matrices a setup stored, without
 * OGRE's frustum update: OGRE 1.12 asserts (and aborts) in
 * Frustum::updateFrustumImpl when a custom projection has NaN entries, so
 * the check must look before anything asks the frustum. */
class ProbeCamera : public Ogre::Camera {
public:
    ProbeCamera(const Ogre::String& name, Ogre::SceneManager* sm) : Ogre::Camera(name, sm) {}
    /* the custom matrices (when set) are finite */
    bool storedMatricesFinite() const;
};

/* The scene manager of OGRE's default (generic) type with the shadow loop of
 * prepareShadowTextures and the visibility pass of _renderScene. */
class HeadlessSceneManager : public Ogre::SceneManager {
public:
    explicit HeadlessSceneManager(const Ogre::String& name);
    ~HeadlessSceneManager() override;
    const Ogre::String& getTypeName(void) const override;
    /* the texture cameras as ensureShadowTexturesCreated makes them: one per
     * shadow texture, map_size square */
    void createShadowCameras(size_t count, unsigned map_size);
    /* One frame's shadow pass as _renderScene runs it for cam: scene graph,
     * lights affecting the frustum, per shadow texture the loop of
     * prepareShadowTextures (getShadowCamera, then the texture camera's
     * caster pass, which fills its visible bounds), then the main camera's
     * visibility pass (its receiver bounds, read by the next frame). */
    void renderShadows(Ogre::Camera* cam, Ogre::Viewport* vp);
    /* the texture cameras as new, before a different setup takes them over
     * (a setup leaves state its successor may not reset: projection type,
     * custom matrices) */
    void resetShadowCameras();
    ProbeCamera* shadowCamera(size_t i) const { return mTexCams[i]; }
    /* false when texture camera i was left with non-finite matrices in the
     * last renderShadows: OGRE's caster pass would abort on them (an
     * assertion in Frustum::updateFrustumImpl), so it was not run and the
     * camera's custom matrices were switched off */
    bool shadowCameraUsable(size_t i) const { return mUsable[i]; }
    size_t shadowCameraCount() const { return mTexCams.size(); }

private:
    void findVisible(Ogre::Camera* cam, bool only_casters);
    std::vector<ProbeCamera*> mTexCams;
    std::vector<bool> mUsable;
    std::vector<std::unique_ptr<SizedTarget>> mTexTargets;
};

/* Root without plugins and without a config file, the default hardware
 * buffer manager (meshes and manual objects in memory) and the null render
 * system; torn down in reverse order. */
class HeadlessRoot {
public:
    HeadlessRoot();
    ~HeadlessRoot();
    HeadlessRoot(const HeadlessRoot&) = delete;
    HeadlessRoot& operator=(const HeadlessRoot&) = delete;

private:
    Ogre::LogManager* mLog;
    Ogre::Root* mRoot;
    Ogre::DefaultHardwareBufferManager* mBuffers;
    NullRenderSystem* mRenderSystem;
};

} // namespace swarp_ogre_test

#endif
