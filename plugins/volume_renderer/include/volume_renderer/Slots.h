#pragma once
#include <string>
#include <vector>

namespace volren {

/// A shader-function slot. Signatures are declared in shaders/slots.glsl.
/// Template slots hold N instances (N clip shapes): each instance's function and uniforms get
/// the suffix _k, and the compositor writes the slot's function as a dispatcher over them.
/// Which implementation a slot gets by default is the CompositionPolicy's business.
struct SlotInfo
{
    std::string name = {};        ///< e.g. "Classification"
    std::string function = {};    ///< GLSL function name, e.g. "volren_classify"
    bool isTemplate = false;      ///< instantiated once per clip shape
    /// A multi-volume set's program has one of it for all members (the ray, its march, its
    /// start offset, its skipping); every other slot is compiled in once per member.
    bool perSet = false;
    std::string signature = {};   ///< full GLSL signature (template slots: used by the dispatcher)
    std::string call = {};        ///< template slots: call of instance {k}
    std::string join = {};        ///< template slots: text between calls
    std::string wrap = {};        ///< template slots: body around the joined calls ({calls})
    std::string empty = {};       ///< template slots: body when there are no instances
};

/// All slots, callees first (the order their implementations are emitted in).
const std::vector<SlotInfo>& slots();
/// The slot named `name`, or null.
const SlotInfo* findSlot(const std::string& name);

}  // namespace volren
