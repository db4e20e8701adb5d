#pragma once
#include <volume_reference/ReferenceRenderer.h>

namespace volren {

class CompositionPolicy;
class VolumeScene;
struct ChosenComposition;

/// The reference of a scene as the renderer draws it: the ReferenceScene and ReferenceOptions
/// for renderReference().
struct ReferenceSetup
{
    ReferenceScene scene;
    ReferenceOptions options;
};

/// Makes `placed` the volume as `chosen` draws it: its implementations (the lighting models they
/// declare), its shadows and occlusion from its Shadowing's declared model, whether it darkens
/// the opaque geometry (an implementation needing a kind of data that does), its blending from
/// the set traversal `policy` would march it by.
void applyChoice(ReferenceScene::Placed& placed, const ChosenComposition& chosen, const CompositionPolicy& policy);

/// The volumes of `scene`, each lit as its CompositionPolicy chooses (Shading and Illumination
/// from the lights that reach it, the pass's `lighting` and forced-null slots applied; shadows
/// from its Shadowing: null none, ray exact), its clip shapes and lights. No GL.
ReferenceScene referenceScene(VolumeScene& scene);

/// What `volren reference` and `volren bench` measure against: `scene` seen by `camera` with
/// - each volume lit as the scene's CompositionPolicy chooses (Shading and Illumination from the
///   lights that reach it, the pass's `lighting` and forced-null slots applied; exact shadows
///   where its Shadowing approximates them),
/// - its clip shapes and lights,
/// - its opaque geometry rasterised once for the same camera with every volume hidden, so that
///   the rays end at its depth and the volumes are composited over its colour (`options`'
///   background behind it).
/// Part of the `volume_reference_setup` library, which links the renderer (the reference itself
/// does not). Throws std::runtime_error when the scene shows no volume.
ReferenceSetup referenceSetup(VolumeScene& scene, const ReferenceCamera& camera, ReferenceOptions options = {});

}  // namespace volren
