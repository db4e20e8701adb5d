#include <volume_renderer/Composition.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

namespace volren {

std::string Composition::functionFor(const std::string& slot) const
{
    if (auto it = choice.find(slot); it != choice.end()) return it->second;
    return CompositionPolicy::defaultImplementation(slot);
}

const std::vector<std::string>& Composition::instancesOf(const std::string& slot) const
{
    static const std::vector<std::string> none;
    auto it = instances.find(slot);
    return it == instances.end() ? none : it->second;
}

std::string Composition::key() const
{
    std::string key;
    for (const SlotInfo& s : slots()) {
        key += s.name + "=";
        if (s.isTemplate) {
            key += "[";
            const std::vector<std::string>& list = instancesOf(s.name);
            for (std::size_t i = 0; i < list.size(); ++i) key += (i ? "," : "") + list[i];
            key += "]";
        } else {
            key += functionFor(s.name);
        }
        key += ";";
    }
    key += "lights=" + std::to_string(lightCount) + ";";
    key += keyFragments;
    if (!members.empty()) {
        key += "members{";
        for (const Composition& m : members) key += m.key() + "|";
        key += "}";
    }
    return key;
}

}  // namespace volren
