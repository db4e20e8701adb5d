// GLSL source rewriting for the compositor: renaming identifiers, template instances and set
// members apart, unrolling the set traversal's member loops, the member dispatchers.
#include "GlslRewriting.h"

#include <regex>
#include <sstream>
#include <stdexcept>

namespace volren {

std::string replaceAll(std::string text, const std::string& from, const std::string& to)
{
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

std::string renameIdentifier(const std::string& text, const std::string& from, const std::string& to)
{
    return std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
}

std::set<std::string> definedNames(const std::string& text)
{
    static const std::regex definition(R"((?:^|\n)(?:float|int|bool|void|vec[234]|mat[234])\s+(volren_\w+))");
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), definition); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1].str());
    return names;
}

std::string renameForMember(const std::string& text, const std::set<std::string>& shared, const std::string& suffix,
                            const std::set<std::string>& macros)
{
    static const std::regex name(R"(\b(volren_\w+|VOLREN_\w+)\b)");
    std::string out;
    auto last = text.cbegin();
    for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator(); ++it) {
        out.append(last, text.cbegin() + it->position());
        out += it->str();
        const bool macro = it->str().rfind("VOLREN_", 0) == 0;
        if (macro ? macros.count(it->str()) > 0 : !shared.count(it->str())) out += suffix;
        last = text.cbegin() + it->position() + it->length();
    }
    out.append(last, text.cend());
    return out;
}

std::string unrollMemberLoops(const std::string& text, std::size_t members)
{
    static const std::regex header(
        R"(for\s*\(\s*int\s+k\s*=\s*0\s*;\s*k\s*<\s*VOLREN_MEMBER_COUNT\s*(?:&&\s*([^;]+?))?\s*;\s*\+\+k\s*\)\s*\{)");
    static const std::regex breaks(R"(\bbreak\b)");
    std::string out;
    std::size_t from = 0;
    for (std::smatch m; std::regex_search(text.cbegin() + std::ptrdiff_t(from), text.cend(), m, header);) {
        const std::size_t start = from + std::size_t(m.position());
        const std::size_t open = start + std::size_t(m.length()) - 1;
        std::size_t close = open;
        for (int depth = 0; close < text.size(); ++close) {
            depth += text[close] == '{' ? 1 : text[close] == '}' ? -1 : 0;
            if (depth == 0) break;
        }
        if (close >= text.size()) throw std::runtime_error("a loop over the members has no closing brace");
        const std::string body = text.substr(open + 1, close - open - 1);
        if (std::regex_search(body, breaks))
            throw std::runtime_error("a loop over the members has a break (written out per member, it would end one "
                                     "member's pass only)");
        const std::string condition = m[1].matched ? m[1].str() : std::string();
        out.append(text, from, start - from);
        for (std::size_t k = 0; k < members; ++k)
            out += "do { const int k = " + std::to_string(k) + ";" +
                   (condition.empty() ? std::string() : " if (!(" + condition + ")) break;") + body + "} while (false);";
        // What follows keeps its line numbers (compile errors name the file's own lines).
        out += "\n#line " + std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(close), '\n')) + "\n";
        from = close + 1;
    }
    out.append(text, from, std::string::npos);
    return out;
}

std::string memberDispatchers(const std::string& glue, std::size_t members)
{
    // `T volren_memberX(params)` defined by the glue -> `T volren_setMemberX(int k, params)`
    // calling member k's copy; an index out of range returns T's zero.
    static const std::regex definition(
        R"((?:^|\n)(void|float|bool|int|vec[234])\s+volren_member(\w+)\s*\(([^)]*)\)\s*\{)");
    static const std::regex parameterName(R"((\w+)\s*$)");
    std::string out;
    for (auto it = std::sregex_iterator(glue.begin(), glue.end(), definition); it != std::sregex_iterator(); ++it) {
        const std::string type = (*it)[1], name = (*it)[2], parameters = (*it)[3];
        std::string arguments;
        std::stringstream list(parameters);
        for (std::string parameter; std::getline(list, parameter, ',');) {
            std::smatch m;
            if (!std::regex_search(parameter, m, parameterName))
                throw std::runtime_error("MultiVolume/member: cannot read parameter '" + parameter + "' of volren_member" + name);
            arguments += (arguments.empty() ? "" : ", ") + m[1].str();
        }
        out += type + " volren_setMember" + name + "(int k" + (parameters.find_first_not_of(" \n") == std::string::npos ? "" : ", " + parameters) +
               ")\n{\n";
        for (std::size_t k = 0; k < members; ++k)
            out += std::string(k ? "    else if" : "    if") + " (k == " + std::to_string(k) + ") " +
                   (type == "void" ? "" : "return ") + "volren_member" + name + "_v" + std::to_string(k) + "(" +
                   arguments + ");\n";
        if (type == "bool") out += "    return false;\n";
        else if (type != "void") out += "    return " + type + "(0);\n";
        out += "}\n";
    }
    return out;
}

}  // namespace volren
