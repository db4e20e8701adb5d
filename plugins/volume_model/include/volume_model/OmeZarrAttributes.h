#pragma once
#include <string>
#include <vector>

namespace volren {

/// One axis of an OME-Zarr image.
struct OmeZarrAxis
{
    std::string name;  ///< "t", "c", "z", "y", "x" or another name
    std::string type;  ///< "time", "channel", "space" or a custom type (inferred from t/c/z/y/x when absent)
    std::string unit;  ///< e.g. "micrometer", "second"; empty when not given
};

/// One resolution level of a multiscale image: its array and where its elements lie.
struct OmeZarrLevel
{
    std::string path;                 ///< array folder relative to the image group ("0")
    std::vector<double> scale;        ///< per axis: element size (voxel spacing, time step), multiscale-wide scale applied
    std::vector<double> translation;  ///< per axis: position of element 0 (zeros when not given)
};

/// Display hints of one channel (`omero` metadata), plain data for the microscopy viewer.
struct OmeroChannel
{
    std::string label;                    ///< channel name ("DAPI"); may be empty
    std::string color;                    ///< "RRGGBB" as in the file; empty when absent
    float red = 1.f, green = 1.f, blue = 1.f;  ///< the colour in [0, 1] (white when absent)
    bool active = true;                   ///< shown by default
    bool hasWindow = false;               ///< whether `window` was given
    double windowMin = 0.0, windowMax = 0.0;      ///< value range of the data (window min/max)
    double windowStart = 0.0, windowEnd = 0.0;    ///< displayed value window (window start/end)
};

/// The OME-Zarr 0.4 metadata in an image group's `.zattrs` (its first `multiscales` entry, the
/// `omero` block and volren's own `volren` block), checked for consistency within itself.
struct OmeZarrAttributes
{
    std::string version;                 ///< multiscales version ("0.4")
    std::string name;                    ///< multiscales name; may be empty
    std::vector<OmeZarrAxis> axes;       ///< in array dimension order: [time] [channel] space (2 or 3)
    std::vector<OmeZarrLevel> levels;    ///< finest first
    std::vector<OmeroChannel> channels;  ///< omero channels; empty when absent
    double rescaleSlope = 1.0;           ///< volren's "rescale": data = stored * slope + intercept
    double rescaleIntercept = 0.0;       ///< volren's "rescale"

    /// Index of the first axis of `type` ("time", "channel", "space"), or -1.
    int axisOfType(const std::string& type) const;
    /// Index of the axis that holds channels: the "channel" axis, else a custom-typed one, or -1.
    int channelAxis() const;
};

/// Parses `.zattrs` text of an OME-Zarr image. Throws std::runtime_error("name: reason") for
/// malformed JSON, a missing or empty multiscales list, bad axes (count, order, duplicates),
/// datasets without a path or with scales that do not match the axes or are not positive and
/// finite, and bad omero colours or windows. Version 0.5 (zarr v3) is refused; earlier
/// versions are read as 0.4 (with spatial scales 2^level when they give none).
OmeZarrAttributes parseOmeZarrAttributes(const std::string& text, const std::string& name);

}  // namespace volren
