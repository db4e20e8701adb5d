#pragma once
#include <osgDB/Serializer>

#include <string>

namespace volren::serializers {

/// Like osgDB::UserSerializer, but whether the property is written may depend on the output
/// stream (its options), not only on the object: embedded voxels are written on request.
template <class C>
class StreamSerializer : public osgDB::BaseSerializer
{
public:
    using Checker = bool (*)(const osgDB::OutputStream&, const C&);  ///< whether to write
    using Reader = bool (*)(osgDB::InputStream&, C&);                ///< reads the value
    using Writer = bool (*)(osgDB::OutputStream&, const C&);         ///< writes the value

    StreamSerializer(const char* name, Checker checker, Reader reader, Writer writer)
        : osgDB::BaseSerializer(READ_WRITE_PROPERTY), _name(name), _checker(checker), _reader(reader), _writer(writer)
    {
    }

    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        if (is.isBinary()) {
            bool present = false;
            is >> present;
            if (!present) return true;
        } else if (!is.matchString(_name)) {
            return true;
        }
        return _reader(is, static_cast<C&>(obj));
    }

    bool write(osgDB::OutputStream& os, const osg::Object& obj) override
    {
        const C& object = static_cast<const C&>(obj);
        const bool present = _checker(os, object);
        if (os.isBinary())
            os << present;
        else if (present)
            os << os.PROPERTY(_name.c_str());
        return !present || _writer(os, object);
    }

    const std::string& getName() const override { return _name; }  ///< property name

private:
    std::string _name;
    Checker _checker;
    Reader _reader;
    Writer _writer;
};

}  // namespace volren::serializers
