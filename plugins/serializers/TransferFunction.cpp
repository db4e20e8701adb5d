// volren::TransferFunction: control points, the value window when set explicitly, resolution.
#include "StreamFields.h"

#include <volume_model/TransferFunction.h>

#include <osgDB/ObjectWrapper>

namespace {

using namespace volren::serializers;
using volren::TransferFunction;

bool checkPoints(const TransferFunction& tf) { return !tf.points().empty(); }

/// One line per point: data value, then r g b a.
bool writePoints(osgDB::OutputStream& os, const TransferFunction& tf)
{
    writeInt(os, std::int64_t(tf.points().size()));
    os << os.BEGIN_BRACKET << std::endl;
    for (const auto& [value, rgba] : tf.points()) {
        writeDouble(os, value);
        for (int i = 0; i < 4; ++i) writeFloat(os, rgba[i]);
        os << std::endl;
    }
    os << os.END_BRACKET << std::endl;
    return true;
}

bool readPoints(osgDB::InputStream& is, TransferFunction& tf)
{
    const std::string field = "volren::TransferFunction Points";
    std::int64_t count = 0;
    if (!readInt(is, count, 0, 1 << 24, field)) return false;
    is >> is.BEGIN_BRACKET;
    for (std::int64_t n = 0; n < count; ++n) {
        double value = 0.0;
        osg::Vec4 rgba;
        if (!readDouble(is, value, field)) return false;
        for (int i = 0; i < 4; ++i)
            if (!readFloat(is, rgba[i], field)) return false;
        try {
            tf.setPoint(value, rgba);
        } catch (const std::exception& e) {
            return fail(is, field + ": " + e.what()), false;
        }
    }
    is >> is.END_BRACKET;
    return !is.getException();
}

bool checkDomain(const TransferFunction& tf) { return tf.hasExplicitDomain(); }

bool writeDomain(osgDB::OutputStream& os, const TransferFunction& tf)
{
    writeDouble(os, tf.domainMin());
    writeDouble(os, tf.domainMax());
    os << std::endl;
    return true;
}

bool readDomain(osgDB::InputStream& is, TransferFunction& tf)
{
    const std::string field = "volren::TransferFunction Domain";
    double lo = 0.0, hi = 1.0;
    if (!readDouble(is, lo, field) || !readDouble(is, hi, field)) return false;
    try {
        tf.setDomain(lo, hi);
    } catch (const std::exception& e) {
        return fail(is, field + ": " + e.what()), false;
    }
    return true;
}

bool checkResolution(const TransferFunction&) { return true; }

bool writeResolution(osgDB::OutputStream& os, const TransferFunction& tf)
{
    writeInt(os, tf.resolution());
    os << std::endl;
    return true;
}

bool readResolution(osgDB::InputStream& is, TransferFunction& tf)
{
    const std::string field = "volren::TransferFunction Resolution";
    std::int64_t entries = 0;
    if (!readInt(is, entries, 0, 1 << 30, field)) return false;
    try {
        tf.setResolution(unsigned(entries));
    } catch (const std::exception& e) {
        return fail(is, field + ": " + e.what()), false;
    }
    return true;
}

bool checkInterpolation(const TransferFunction&) { return true; }

bool writeInterpolation(osgDB::OutputStream& os, const TransferFunction& tf)
{
    os << std::string(tf.interpolation() == TransferFunction::Interpolation::MonotoneCubic ? "MonotoneCubic" : "Linear")
       << std::endl;
    return true;
}

bool readInterpolation(osgDB::InputStream& is, TransferFunction& tf)
{
    std::string mode;
    is >> mode;
    if (mode == "Linear") tf.setInterpolation(TransferFunction::Interpolation::Linear);
    else if (mode == "MonotoneCubic") tf.setInterpolation(TransferFunction::Interpolation::MonotoneCubic);
    else return fail(is, "volren::TransferFunction Interpolation: '" + mode + "' is not Linear or MonotoneCubic"), false;
    return true;
}

}  // namespace

REGISTER_OBJECT_WRAPPER(volren_TransferFunction, new volren::TransferFunction, volren::TransferFunction,
                        "osg::Object volren::TransferFunction")
{
    ADD_USER_SERIALIZER(Points);
    ADD_USER_SERIALIZER(Domain);
    ADD_USER_SERIALIZER(Resolution);
    ADD_USER_SERIALIZER(Interpolation);  // newer than the other fields: an older .osgb lacks it
}
