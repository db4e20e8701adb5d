#pragma once
#include <osg/Object>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>

#include <cstdint>
#include <string>

namespace volren::serializers {

// Field values on an osgDB stream, exact and strict: numbers in text files are written with
// enough digits to read back bit-identical (independent of OSG's PRECISION option) and read
// back only when the whole token is a number; anything else fails the read with a message
// that names the field. Binary files hold the raw values.

/// Shortest decimal text of `v` that reads back as exactly `v`.
std::string exactNumber(double v);

/// Fails the read with `message`, also logged as a warning (OSG keeps parsing after a failure
/// and a later failure of its own may replace the message in the ReadResult).
void fail(osgDB::InputStream& is, const std::string& message);

/// Writes `v` exactly.
void writeDouble(osgDB::OutputStream& os, double v);
/// Reads a finite double into `v`; false (read failed, naming `field`) when it is not one.
bool readDouble(osgDB::InputStream& is, double& v, const std::string& field);
/// Writes `v` exactly.
void writeFloat(osgDB::OutputStream& os, float v);
/// Reads a finite float into `v`; false (read failed, naming `field`) when it is not one.
bool readFloat(osgDB::InputStream& is, float& v, const std::string& field);
/// Writes an integer.
void writeInt(osgDB::OutputStream& os, std::int64_t v);
/// Reads an integer in [lo, hi] into `v`; false (read failed, naming `field`) otherwise.
bool readInt(osgDB::InputStream& is, std::int64_t& v, std::int64_t lo, std::int64_t hi, const std::string& field);
/// Writes a bool (TRUE / FALSE in text).
void writeBool(osgDB::OutputStream& os, bool v);
/// Reads a bool; in text only TRUE or FALSE; false (read failed, naming `field`) otherwise.
bool readBool(osgDB::InputStream& is, bool& v, const std::string& field);

/// Writes a string (any bytes). Text files hold it quoted with `%XX` for whitespace, quotes,
/// backslashes and `%`, so it is one token; OSG's own readWrappedString loops forever on a text
/// file that ends inside a quoted string, so volren fields never use it.
void writeString(osgDB::OutputStream& os, const std::string& v);
/// Reads a string written by writeString (in text also a quoted string with plain single
/// spaces, as people write it); false (read failed, naming `field`) on a bad or cut string.
bool readString(osgDB::InputStream& is, std::string& v, const std::string& field);

/// Writes the name of a property inside a compound value.
void writeProperty(osgDB::OutputStream& os, const char* name);
/// Reads a property name; false (read failed, naming `field`) when another name is there.
bool readProperty(osgDB::InputStream& is, const char* name, const std::string& field);

/// Writes `object` (or nothing) as a bracketed nested object; shared objects are written once
/// and referenced by their unique id afterwards, so sharing survives the round trip.
void writeObjectField(osgDB::OutputStream& os, const osg::Object* object);
/// Reads a nested object written by writeObjectField; fails naming `field` when it is missing,
/// unreadable or not a `T`.
template <class T>
bool readObjectField(osgDB::InputStream& is, osg::ref_ptr<T>& out, const std::string& field, const char* typeName)
{
    is >> is.BEGIN_BRACKET;
    if (is.getException()) {  // the read already failed: skip the object, staying in step
        is.advanceToCurrentEndBracket();
        return false;
    }
    osg::ref_ptr<osg::Object> object = is.readObject();
    is >> is.END_BRACKET;
    if (is.getException()) return false;
    out = dynamic_cast<T*>(object.get());
    if (out) return true;
    fail(is, field + (object ? std::string(" is a ") + object->libraryName() + "::" + object->className() +
                                   ", not a " + typeName
                             : std::string(": missing or unreadable ") + typeName));
    return false;
}

}  // namespace volren::serializers
