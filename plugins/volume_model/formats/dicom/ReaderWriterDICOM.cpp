// osgDB plugin for DICOM series through GDCM: a directory, or any one slice file of a series
// (.dcm/.dic/.dicom), reads the whole series; readObject gives a volren::Volume, readNode the
// default scene. Named osgdb_dicom because OSG's registry maps .dcm and .dic to "dicom".
#include "DicomSeriesReader.h"
#include "DicomSeriesScan.h"

#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <sstream>
#include <stdexcept>

namespace {

class ReaderWriterDICOM : public volren::VolumeReaderWriter
{
public:
    ReaderWriterDICOM()
    {
        supportsExtension("dcm", "DICOM slice: reads the whole series of its directory");
        supportsExtension("dic", "DICOM slice: reads the whole series of its directory");
        supportsExtension("dicom", "DICOM series: a directory or one slice file");
        supportsOption("DicomSeries=<UID>", "SeriesInstanceUID to read when a directory holds several series");
    }

    const char* className() const override { return "volren DICOM series reader (GDCM)"; }

protected:
    /// A directory (the series in it) or one slice file (its series).
    std::string locate(const std::string& file, const Options* options) const override
    {
        return osgDB::fileType(file) == osgDB::DIRECTORY ? file : VolumeReaderWriter::locate(file, options);
    }

    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        const auto slices = volren::dicom::findSeries(path, seriesOption(options));
        const auto order = volren::dicom::orderSlices(slices, path);
        return ReadResult(volren::dicom::readSeries(order, path, options).get());
    }

private:
    /// Value of the option DicomSeries=<UID> in the options string, or empty.
    static std::string seriesOption(const Options* options)
    {
        if (!options) return {};
        std::istringstream words(options->getOptionString());
        for (std::string word; words >> word;)
            if (word.rfind("DicomSeries=", 0) == 0) return word.substr(12);
        return {};
    }
};

}  // namespace

REGISTER_OSGPLUGIN(dicom, ReaderWriterDICOM)
