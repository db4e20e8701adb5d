#pragma once
#include <string>

namespace volren::dicom {

/// Walks the data elements of a DICOM file (Part 10: preamble, "DICM", explicit-VR file meta
/// group, then the data set in its transfer syntax, sequences and encapsulated pixel data
/// included) and returns what is wrong with its structure: an element whose length runs past the
/// end of the file, a truncated tag, an unterminated sequence. "" when the structure is sound or
/// cannot be walked (no "DICM" preamble, deflated data set): GDCM judges those.
/// Debian's GDCM 3.0 aborts the process (a failed assert) on some such files, so the scan checks
/// every file here first.
std::string structureProblem(const std::string& file);

}  // namespace volren::dicom
