#pragma once
// Internal to the compositor: rewriting GLSL source text as ProgramAssembly composes it.
#include <cstddef>
#include <set>
#include <string>

namespace volren {

/// `text` with every `from` replaced by `to`.
std::string replaceAll(std::string text, const std::string& from, const std::string& to);
/// Renames whole-word identifier `from` to `to` in GLSL source.
std::string renameIdentifier(const std::string& text, const std::string& from, const std::string& to);
/// Names a file defines at its top level (functions and global variables).
std::set<std::string> definedNames(const std::string& text);
/// Gives every volren_ name in `text` that is not in `shared` the member suffix, and the
/// per-composition macros (`macros`: the light count and the implementations' defines) too.
std::string renameForMember(const std::string& text, const std::set<std::string>& shared, const std::string& suffix,
                            const std::set<std::string>& macros);
/// The set traversal's loops over members, `for (int k = 0; k < VOLREN_MEMBER_COUNT[ && C]; ++k)
/// { body }`, written out once per member: `do { const int k = <n>; [if (!(C)) break;] body }
/// while (false);` (a `continue` in the body ends that member's pass, as in the loop). A member's
/// dispatchers then see a constant k and call it alone: GPUs that run both sides of a branch
/// under a mask (llvmpipe) would otherwise pay every member's code for each call. C must stay
/// false once it is false (it is checked before each member); a `break` in the body is refused.
std::string unrollMemberLoops(const std::string& text, std::size_t members);
/// For each function `volren_memberX` the member glue source defines, `volren_setMemberX` with
/// the member index first, calling that member's copy (of `members`).
std::string memberDispatchers(const std::string& glue, std::size_t members);

}  // namespace volren
