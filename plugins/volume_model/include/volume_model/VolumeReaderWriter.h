#pragma once
#include <osgDB/ReaderWriter>

#include <string>

namespace volren {

/// Base of the volren osgDB volume plugins: readObject gives the volren::Volume, readNode the
/// default scene for it (makeDefaultScene), both for the file names this plugin supports
/// (supportsExtension; a trailing `.gz` is looked through). A format implements readVolume.
class VolumeReaderWriter : public osgDB::ReaderWriter
{
public:
    ReadResult readObject(const std::string& file, const Options* options) const override;
    ReadResult readNode(const std::string& file, const Options* options) const override;

protected:
    /// Reads `path` (from locate); returns a Volume, or an error. An exception thrown here
    /// becomes an error whose message names `path`, unless its text already does.
    virtual ReadResult readVolume(const std::string& path, const Options* options) const = 0;
    /// Whether `file` has an extension this plugin supports (`.gz` looked through).
    bool handles(const std::string& file) const;
    /// The path to read for `file`: "" when this plugin does not handle it, the file as found
    /// on OSG's data path otherwise (formats that read directories or patterns override it).
    virtual std::string locate(const std::string& file, const Options* options) const;
    /// A Volume result turned into its default scene; errors pass through.
    static ReadResult asScene(ReadResult volume);
};

}  // namespace volren
