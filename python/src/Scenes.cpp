#include "Scenes.h"
#include "Conversions.h"
#include "Settings.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/SceneInputs.h>
#include <volume_renderer/SceneSettings.h>

#include <osgDB/Options>

#include <map>
#include <vector>

namespace py = pybind11;

namespace volren::python {

namespace {

std::vector<std::string> inputPaths(const py::handle& inputs)
{
    if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__")) return {pathFrom(inputs, "inputs")};
    if (!py::isinstance<py::list>(inputs) && !py::isinstance<py::tuple>(inputs))
        throw py::type_error("inputs: expected None, a path or a list of paths, got " + reprOf(inputs));
    std::vector<std::string> paths;
    for (const py::handle item : inputs) paths.push_back(pathFrom(item, "inputs"));
    return paths;
}

/// `place` as placements by 0-based input index, checked as --place is.
std::map<std::size_t, Placement> placements(const py::handle& place, std::size_t inputs)
{
    std::map<std::size_t, Placement> placed;
    if (place.is_none()) return placed;
    if (!py::isinstance<py::dict>(place))
        throw py::type_error("place: expected a dict {input number (1-based): 'tx,ty,tz[:s][:axis,angle]'}, got " +
                             reprOf(place));
    for (const auto& [key, value] : place.cast<py::dict>()) {
        if (py::isinstance<py::bool_>(key) || !py::isinstance<py::int_>(key))
            throw py::type_error("place: keys are input numbers (1-based), got " + reprOf(key));
        const long long n = key.cast<long long>();
        if (n < 1 || std::size_t(n) > inputs)
            throw py::value_error("place " + reprOf(key) + ": there " + (inputs == 1 ? "is " : "are ") +
                                  std::to_string(inputs) + " input" + (inputs == 1 ? "" : "s") + " (numbered from 1)");
        if (!py::isinstance<py::str>(value))
            throw py::type_error("place " + reprOf(key) + ": expected 'tx,ty,tz[:s][:axis,angle]', got " + reprOf(value));
        try {
            placed[std::size_t(n - 1)] = parsePlacement(value.cast<std::string>());
        } catch (const std::invalid_argument& e) {
            throw py::value_error("place " + reprOf(key) + ": " + e.what());
        }
    }
    return placed;
}

}  // namespace

osg::ref_ptr<VolumeScene> volumeScene(Volume& volume)
{
    return asVolumeScene(makeDefaultScene(&volume).get());
}

osg::ref_ptr<VolumeScene> inputsScene(const py::handle& inputs, const py::handle& place, const std::string& readerOptions)
{
    if (inputs.is_none()) {
        if (!place.is_none() && py::len(place) > 0) throw py::value_error("place: the default scene has no inputs to place");
        return asVolumeScene(readDefaultScene().get());
    }
    const std::vector<std::string> paths = inputPaths(inputs);
    if (paths.empty()) throw py::value_error("inputs: the list is empty (None renders the default scene)");
    const std::map<std::size_t, Placement> placed = placements(place, paths.size());
    std::vector<SceneInput> sceneInputs;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const auto p = placed.find(i);
        sceneInputs.push_back({paths[i], p == placed.end() ? std::nullopt : std::optional<Placement>(p->second)});
    }
    const osg::ref_ptr<osgDB::Options> options = new osgDB::Options(readerOptions);
    osg::ref_ptr<osg::Group> scene =
        readSceneInputs(sceneInputs, [&](const std::string& path) { return readVolumeFile(path, options.get()); });
    return asVolumeScene(scene.get());
}

std::string readerOptionsText(const py::handle& options)
{
    if (options.is_none()) return {};
    if (py::isinstance<py::str>(options)) return options.cast<std::string>();
    if (!py::isinstance<py::dict>(options))
        throw py::type_error("reader options: expected a str or a dict, got " + reprOf(options));
    std::string text;
    for (const auto& [key, value] : options.cast<py::dict>()) {
        const std::string name = py::str(key);
        std::string option;
        if (value.is_none() || (py::isinstance<py::bool_>(value) && !value.cast<bool>())) continue;
        if (py::isinstance<py::bool_>(value)) option = name;  // a flag: lazy=True -> "lazy"
        else option = name + "=" + settingText(name, value);
        text += (text.empty() ? "" : " ") + option;
    }
    return text;
}

}  // namespace volren::python
