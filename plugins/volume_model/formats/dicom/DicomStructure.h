#pragma once
#include <string>

namespace volren::dicom {

/// What structureProblem found.
struct Structure
{
    bool part10 = false;  ///< the file has the Part 10 preamble ("DICM" at byte 128)
    std::string problem;  ///< "" when the elements are sound (or, deflated, cannot be walked)
    bool pixelData = false;  ///< the data set has a Pixel Data element (7FE0,0010) at its top level
};

/// Walks the data elements of a file as DICOM: a Part 10 file (preamble, "DICM", explicit-VR
/// file meta group, then the data set in its transfer syntax) or a bare data set (explicit VR
/// little endian when its first element has a VR, else implicit), sequences and encapsulated
/// pixel data included, and says what is wrong with its structure: an element whose length runs
/// past the end of the file, a truncated tag, an unterminated sequence. Debian's GDCM 3.0 aborts
/// the process (a failed assert) on some such files, so the scan checks every file here first.
Structure structureProblem(const std::string& file);

}  // namespace volren::dicom
