#pragma once
#include <volume_model/Volume.h>
#include <volume_renderer/VolumeScene.h>

#include <pybind11/pybind11.h>

#include <string>

namespace volren::python {

/// The scene `volren render FILE` gives a volume file: the volume centred at the origin with a
/// transfer function from its histogram and one headlight, under a VolumeScene.
osg::ref_ptr<VolumeScene> volumeScene(Volume& volume);

/// The scene of `volren render INPUT...`: None the default scene, a path or a list of paths
/// (scene, volume and model files) combined by readSceneInputs; `place` maps 1-based input
/// numbers to "tx,ty,tz[:s][:axis,angle]" (--place N:SPEC); volumes are read with
/// `readerOptions` (-O). ValueError / TypeError for bad arguments, volren.Error for bad files.
osg::ref_ptr<VolumeScene> inputsScene(const pybind11::handle& inputs, const pybind11::handle& place,
                                      const std::string& readerOptions);

/// Reader options (a str as -O takes it, or a dict: {'lazy': True, 'ramBudgetMB': 64}) as the
/// osgDB::Options string: "lazy ramBudgetMB=64"; a False or None entry is left out.
std::string readerOptionsText(const pybind11::handle& options);

}  // namespace volren::python
