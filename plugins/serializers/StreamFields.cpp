#include "StreamFields.h"

#include <volume_model/ParseNumber.h>

#include <osg/Notify>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace volren::serializers {

namespace {

/// Shortest decimal text of `v` with at least `minDigits` significant digits that reads back as `v`.
template <class T>
std::string exactText(T v, int minDigits, int maxDigits)
{
    char buffer[64];
    for (int digits = minDigits; digits <= maxDigits; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, double(v));
        if (T(std::strtod(buffer, nullptr)) == v) break;
    }
    return buffer;
}

std::string readToken(osgDB::InputStream& is)
{
    std::string token;
    is >> token;
    return token;
}

}  // namespace

std::string exactNumber(double v)
{
    return exactText(v, 1, 17);
}

void fail(osgDB::InputStream& is, const std::string& message)
{
    // Also a warning: OSG reads on after an error and may replace it by a later, vaguer one
    // ("Failed to read from stream") when the rest of the file no longer parses.
    OSG_WARN << message << std::endl;
    if (!is.getException()) is.throwException(message);
}

void writeDouble(osgDB::OutputStream& os, double v)
{
    if (os.isBinary())
        os << v;
    else
        os << exactText(v, 6, 17);
}

bool readDouble(osgDB::InputStream& is, double& v, const std::string& field)
{
    if (is.isBinary()) {
        is >> v;
    } else {
        const std::string token = readToken(is);
        if (is.getException()) return false;
        if (!parseFiniteNumber(token, v)) return fail(is, field + ": expected a number, got '" + token + "'"), false;
    }
    if (is.getException()) return false;
    if (!std::isfinite(v)) return fail(is, field + ": expected a finite number"), false;
    return true;
}

void writeFloat(osgDB::OutputStream& os, float v)
{
    if (os.isBinary())
        os << v;
    else
        os << exactText(v, 6, 9);
}

bool readFloat(osgDB::InputStream& is, float& v, const std::string& field)
{
    if (is.isBinary()) {
        is >> v;
        if (is.getException()) return false;
        if (!std::isfinite(v)) return fail(is, field + ": expected a finite number"), false;
        return true;
    }
    double d = 0.0;
    if (!readDouble(is, d, field)) return false;
    v = float(d);
    if (!std::isfinite(v)) return fail(is, field + ": " + std::to_string(d) + " is out of float range"), false;
    return true;
}

void writeInt(osgDB::OutputStream& os, std::int64_t v)
{
    if (os.isBinary())
        os << double(v);  // OSG's binary stream has no portable 64-bit integer; doubles hold 2^53 exactly
    else
        os << std::to_string(v);
}

bool readInt(osgDB::InputStream& is, std::int64_t& v, std::int64_t lo, std::int64_t hi, const std::string& field)
{
    double d = 0.0;
    if (is.isBinary()) {
        is >> d;
        if (is.getException()) return false;
    } else {
        const std::string token = readToken(is);
        if (is.getException()) return false;
        if (!parseFiniteNumber(token, d) || d != std::floor(d))
            return fail(is, field + ": expected an integer, got '" + token + "'"), false;
    }
    if (!(d >= double(lo) && d <= double(hi)))
        return fail(is, field + ": " + exactText(d, 6, 17) + " is not in [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]"),
               false;
    v = std::int64_t(d);
    return true;
}

void writeBool(osgDB::OutputStream& os, bool v)
{
    os << v;  // TRUE / FALSE in text, one byte in binary
}

bool readBool(osgDB::InputStream& is, bool& v, const std::string& field)
{
    if (is.isBinary()) {
        is >> v;
        return !is.getException();
    }
    const std::string token = readToken(is);
    if (is.getException()) return false;
    if (token == "TRUE" || token == "FALSE") return v = token == "TRUE", true;
    return fail(is, field + ": expected TRUE or FALSE, got '" + token + "'"), false;
}

void writeString(osgDB::OutputStream& os, const std::string& v)
{
    if (os.isBinary()) {
        os << v;
        return;
    }
    static const char digits[] = "0123456789ABCDEF";
    std::string quoted = "\"";
    for (const char c : v) {
        const auto u = static_cast<unsigned char>(c);
        if (u <= ' ' || u == 0x7f || c == '"' || c == '\\' || c == '%') {
            quoted += '%';
            quoted += digits[u >> 4];
            quoted += digits[u & 15];
        } else {
            quoted += c;
        }
    }
    os << quoted + "\"";
}

bool readString(osgDB::InputStream& is, std::string& v, const std::string& field)
{
    if (is.isBinary()) {
        is >> v;
        return !is.getException();
    }
    std::string text = readToken(is);
    if (is.getException()) return false;
    if (text.empty() || text[0] != '"') {  // a bare word
        v = text;
        return true;
    }
    constexpr std::size_t longest = 1 << 16;
    while (text.size() < 2 || text.back() != '"') {
        const std::string more = readToken(is);
        if (is.getException()) return false;
        text += ' ' + more;
        if (text.size() > longest) return fail(is, field + ": unterminated string"), false;
    }
    v.clear();
    for (std::size_t i = 1; i + 1 < text.size(); ++i) {
        if (text[i] != '%') {
            v += text[i];
            continue;
        }
        const std::string hex = text.substr(i + 1, 2);
        if (hex.size() != 2 || !std::isxdigit(static_cast<unsigned char>(hex[0])) ||
            !std::isxdigit(static_cast<unsigned char>(hex[1])))
            return fail(is, field + ": bad escape '%" + hex + "' in " + text), false;
        v += char(std::strtol(hex.c_str(), nullptr, 16));
        i += 2;
    }
    return true;
}

void writeProperty(osgDB::OutputStream& os, const char* name)
{
    os << os.PROPERTY(name);
}

bool readProperty(osgDB::InputStream& is, const char* name, const std::string& field)
{
    osgDB::ObjectProperty property(name);
    is >> property;  // text: the name found replaces the expected one (OSG also warns)
    if (is.getException()) return false;
    if (property._name != name)
        return fail(is, field + ": expected " + name + ", got '" + property._name + "'"), false;
    return true;
}

void writeObjectField(osgDB::OutputStream& os, const osg::Object* object)
{
    os << os.BEGIN_BRACKET << std::endl;
    os.writeObject(object);
    os << os.END_BRACKET << std::endl;
}

}  // namespace volren::serializers
