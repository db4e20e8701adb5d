#pragma once
#include <volume_model/Volume.h>

#include <string>

namespace volren {

/// Key of the std::string user value of a Volume: the unit of its spacing as its file names it
/// ("micron", "micrometer", "mm"); absent when the file says none.
constexpr const char* spacingUnitKey = "spacingUnit";

/// The short symbol of a length unit as files name it: "µm" for micron, microns, micrometer,
/// micrometre, um, µm (either code point of µ); "nm", "mm", "cm", "m" for theirs and their long
/// names; "" for "", pixel and unit-less names; any other name as it is.
std::string lengthUnitSymbol(const std::string& name);

/// The unit of `volume`'s spacing (its spacingUnitKey user value) as lengthUnitSymbol() writes
/// it, or "" when unknown.
std::string lengthUnitOf(const Volume& volume);

/// `length` in `unit`, rounded to 3 significant digits, written for a label with the prefix
/// that keeps its number in [1, 1000) where the unit is nm, µm, mm or m ("1500 µm" -> "1.5 mm",
/// "0.5 mm" -> "500 µm"); a length without a unit is written alone ("20"). Numbers are written
/// as %g writes them with 12 digits (an exponent only beyond that).
std::string lengthLabel(double length, const std::string& unit);

}  // namespace volren
