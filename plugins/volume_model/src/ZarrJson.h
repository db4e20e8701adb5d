#pragma once
// Internal helpers of the zarr readers (ZarrArrayMetadata.cpp, OmeZarrAttributes.cpp): JSON
// parsing whose errors name the file, and the small checked accessors both need.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace volren::zarrjson {

using Json = nlohmann::json;

/// Parses `text` as JSON; throws std::runtime_error("name: malformed JSON: ...").
inline Json parse(const std::string& text, const std::string& name)
{
    try {
        return Json::parse(text);
    } catch (const Json::parse_error& e) {
        std::string why = e.what();
        if (why.rfind("[json.exception.", 0) == 0 && why.find("] ") != std::string::npos) why = why.substr(why.find("] ") + 2);
        throw std::runtime_error(name + ": malformed JSON: " + why);
    }
}

/// The compact text of `value` for messages, cut after 60 characters.
inline std::string shortText(const Json& value)
{
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

/// `value` as a non-negative integer, or std::runtime_error("name: what is ... , not ...").
inline std::uint64_t unsignedInteger(const Json& value, const std::string& what, const std::string& name)
{
    if (value.is_number_unsigned()) return value.get<std::uint64_t>();
    if (value.is_number_integer() && value.get<std::int64_t>() >= 0) return std::uint64_t(value.get<std::int64_t>());
    throw std::runtime_error(name + ": " + what + " is " + shortText(value) + ", not a non-negative whole number");
}

/// `a * b`, or false when it overflows 64 bits.
inline bool checkedMultiply(std::uint64_t a, std::uint64_t b, std::uint64_t& product)
{
    return !__builtin_mul_overflow(a, b, &product);
}

}  // namespace volren::zarrjson
