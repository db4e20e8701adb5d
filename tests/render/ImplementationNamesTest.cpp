// The generic code never compares with an implementation's name: what it needs to know of an
// implementation, the implementation declares in its entry (plugins/volume_renderer/src/functions/).
// This test reads every source of the plugins, apps and the Python module and fails on a
// comparison (== or !=) with the name of any registered implementation outside those entries.
// Exceptions: "null", the name every slot's null implementation has by convention; the clip kind
// "depth" (ImplementationTraits::clipKind, a trait value that shares the depth clip's name); and
// the words of other vocabularies that happen to be implementation names (`notImplementations`).
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace volren::test {
namespace {

/// Every registered implementation name, but null.
std::set<std::string> implementationNames()
{
    std::set<std::string> names;
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    for (const SlotInfo& slot : slots())
        for (const std::string& name : registry.allNames(slot.name))
            if (name != "null") names.insert(name);
    return names;
}

/// Comparisons with words that are implementation names but mean something else there.
bool notImplementation(const fs::path& file, const std::string& line)
{
    static const std::vector<std::pair<std::string, std::string>> known = {
        {"PassSettings.cpp", "key == \"lighting\""},  // the pass setting `lighting=on|off`
        {"BenchCommand.cpp", "v == \"central\""},     // --normals central|exact (the reference's normals)
        {"ReferenceCommand.cpp", "v == \"central\""},  // the same option of volren reference
    };
    for (const auto& [name, text] : known)
        if (file.filename() == name && line.find(text) != std::string::npos) return true;
    return false;
}

/// "file:line: text" of each comparison with one of `names` in the sources below `folder`.
std::vector<std::string> comparisons(const fs::path& folder, const std::set<std::string>& names)
{
    static const std::regex compared(R"re((?:==|!=)\s*"([a-z0-9_]+)"|"([a-z0-9_]+)"\s*(?:==|!=))re");
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const fs::path& p = entry.path();
        if (!entry.is_regular_file() || (p.extension() != ".cpp" && p.extension() != ".h")) continue;
        if (p.parent_path().filename() == "functions") continue;  // the implementations' own entries
        std::ifstream in(p);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            for (auto it = std::sregex_iterator(line.begin(), line.end(), compared); it != std::sregex_iterator(); ++it) {
                const std::string name = (*it)[1].matched ? (*it)[1].str() : (*it)[2].str();
                static const std::regex clipKind(R"(\b(?:clipKind|kind)\b)");
                if (!names.count(name) || (name == "depth" && std::regex_search(line, clipKind)) ||
                    notImplementation(p, line))
                    continue;
                found.push_back(p.string() + ":" + std::to_string(n) + ": " + line);
            }
    }
    return found;
}

TEST(ImplementationNames, NoGenericCodeComparesWithAnImplementationsName)
{
    const std::set<std::string> names = implementationNames();
    ASSERT_GT(names.size(), 40u);
    std::vector<std::string> found;
    for (const char* folder : {"plugins", "apps", "python"})
        for (const std::string& f : comparisons(fs::path(VOLREN_SOURCE_DIR) / folder, names)) found.push_back(f);
    std::string list;
    for (const std::string& f : found) list += "\n  " + f;
    EXPECT_TRUE(found.empty()) << "comparisons with implementation names outside their entries:" << list;
}

TEST(ImplementationNames, TheScanFindsAComparisonWhereThereIsOne)
{
    // The scan itself, on a planted file: it must report the comparison and skip the entries.
    const fs::path dir = fs::temp_directory_path() / "volren_names_scan";
    fs::remove_all(dir);
    fs::create_directories(dir / "pass");
    fs::create_directories(dir / "functions");
    std::ofstream(dir / "pass" / "Planted.cpp") << "bool f(const std::string& s) { return s == \"mip\"; }\n";
    std::ofstream(dir / "functions" / "Own.cpp") << "bool g(const std::string& s) { return s == \"mip\"; }\n";
    const std::vector<std::string> found = comparisons(dir, implementationNames());
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NE(found[0].find("Planted.cpp:1"), std::string::npos) << found[0];
    fs::remove_all(dir);
}

}  // namespace
}  // namespace volren::test
