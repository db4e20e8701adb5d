#pragma once
#include "CommandLine.h"

#include <volume_renderer/OffscreenRenderer.h>

#include <functional>
#include <string>
#include <vector>

namespace volren::app {

/// What a render wrote: the file (or "first ... last"), and how many frames.
struct WrittenFrames
{
    std::string path;
    int frames = 1;
};

/// Whether the options ask for a sequence of frames (--turntable N, --time all).
bool isSequence(const RenderOptions& options);

/// Renders the sequence the options ask for with `renderer` (scene set): --turntable N views
/// around the scene at one distance, --time all every time point (with a turntable, the time
/// points spread over its frames: frame k shows time point k * T / N). Each frame is rendered,
/// then `converge` lets streamed bricks arrive; frames are written as OUT_0001.png ... or, for
/// OUT.gif, one animated GIF. Appends each frame's timing to `timings`; returns what was written.
WrittenFrames renderSequence(OffscreenRenderer& renderer, osg::Node& scene, const RenderOptions& options,
                           const std::function<void()>& converge, std::vector<FrameTiming>& timings);

}  // namespace volren::app
