#include <volume_model/ChannelDisplay.h>

#include <osg/UserDataContainer>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace volren {

osg::ref_ptr<Volume> channelOf(const Volume& volume, int c, int t)
{
    const std::string name = volume.sourceFile.empty() ? std::string("volume") : volume.sourceFile;
    if (c < 0 || c >= volume.channels())
        throw std::out_of_range(name + ": channel " + std::to_string(c) + " does not exist (it has " +
                                std::to_string(volume.channels()) + ", counted from 0)");
    if (t < 0 || t >= volume.frames())
        throw std::out_of_range(name + ": time point " + std::to_string(t) + " does not exist (it has " +
                                std::to_string(volume.frames()) + ", counted from 0)");
    if (volume.fullResolution() && volume.channels() * volume.frames() > 1)
        throw std::runtime_error(name + ": the channels and time points of a volume opened lazily cannot be shown (read it whole)");
    const std::size_t blockBytes = volume.voxelCount() * voxelSize(volume.type());
    const std::uint8_t* first = volume.block(c, t);
    osg::ref_ptr<Volume> one = new Volume;
    one->assign(volume.type(), volume.dims(), std::vector<std::uint8_t>(first, first + blockBytes));
    one->setSpacing(volume.spacing());
    one->setRescale(volume.rescaleSlope(), volume.rescaleIntercept());
    one->sourceFile = volume.sourceFile;
    if (std::size_t(c) < volume.channelHints.size()) one->channelHints = {volume.channelHints[std::size_t(c)]};
    if (const osg::UserDataContainer* values = volume.getUserDataContainer())  // units, placement, time step
        one->setUserDataContainer(osg::clone(values, osg::CopyOp::DEEP_COPY_ALL));
    return one;
}

osg::ref_ptr<TransferFunction> scaledOpacity(const TransferFunction& tf, double scale)
{
    osg::ref_ptr<TransferFunction> out = new TransferFunction;
    out->assign(tf);
    for (const auto& [value, rgba] : tf.points())
        out->setPoint(value, osg::Vec4(rgba.r(), rgba.g(), rgba.b(), float(std::clamp(double(rgba.a()) * scale, 0.0, 1.0))));
    return out;
}

osg::Vec3 channelColour(int c)
{
    static const osg::Vec3 palette[] = {{0, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    constexpr int n = int(sizeof(palette) / sizeof(palette[0]));
    return palette[((c % n) + n) % n];
}

osg::ref_ptr<TransferFunction> colourWindowTransferFunction(const osg::Vec3& colour, double low, double high, double opacity)
{
    if (!(high > low)) throw std::invalid_argument("colour window: low must be below high");
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(low, osg::Vec4(colour, 0.0f));
    tf->setPoint(high, osg::Vec4(colour, float(opacity)));
    return tf;
}

namespace {

/// The window of a channel's histogram `h` between percentiles `low` and `high` (0..100).
std::pair<double, double> windowOf(const Histogram& h, double low, double high)
{
    double lo = h.percentile(low / 100.0), hi = h.percentile(high / 100.0);
    if (!(hi > lo)) {  // a constant channel (or one value dominating): one bin around it
        const double width = std::max(h.binWidth(), std::max(1.0, std::abs(lo)) * 1e-6);
        lo -= width * 0.5;
        hi = lo + width;
    }
    return {lo, hi};
}

}  // namespace

std::pair<double, double> channelWindow(const Volume& volume, int c, double low, double high)
{
    return windowOf(channelOf(volume, c)->histogram(1024), low, high);
}

namespace {

/// Whether [low, high] spans every value `type` stores: ImageJ's range when none was set.
bool wholeTypeRange(VoxelType type, double low, double high)
{
    switch (type) {
    case VoxelType::UInt8: return low <= 0.0 && high >= 255.0;
    case VoxelType::Int8: return low <= -128.0 && high >= 127.0;
    case VoxelType::UInt16: return low <= 0.0 && high >= 65535.0;
    case VoxelType::Int16: return low <= -32768.0 && high >= 32767.0;
    default: return false;
    }
}

}  // namespace

osg::ref_ptr<TransferFunction> colourTableTransferFunction(const std::vector<osg::Vec3f>& colours, double low, double high,
                                                           double opacity)
{
    if (colours.size() < 2) return colourWindowTransferFunction(colours.empty() ? osg::Vec3(1, 1, 1) : colours[0], low, high, opacity);
    if (!(high > low)) throw std::invalid_argument("colour table: low must be below high");
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    const std::size_t last = colours.size() - 1;
    for (std::size_t i = 0; i <= last; ++i) {
        const double f = double(i) / double(last);
        tf->setPoint(low + f * (high - low), osg::Vec4(colours[i], float(f * opacity)));
    }
    return tf;
}

std::vector<ChannelDisplay> defaultChannelDisplays(const Volume& volume)
{
    std::vector<ChannelDisplay> displays;
    for (int c = 0; c < volume.channels(); ++c) {
        const ChannelHint* hint = std::size_t(c) < volume.channelHints.size() ? &volume.channelHints[std::size_t(c)] : nullptr;
        double low = 0.0, high = 0.0;
        if (hint && hint->hasWindow && !wholeTypeRange(volume.type(), hint->low, hint->high)) {
            low = hint->low, high = hint->high;  // the file's display range
        } else {
            const Histogram h = channelOf(volume, c)->histogram(1024);
            std::tie(low, high) = windowOf(h, 0.5, 99.5);
            // Transparent up to the background (Otsu's threshold of the channel) where it lies in the window.
            const double background = h.otsuThreshold();
            if (background > low && background < high) low = background;
        }
        ChannelDisplay display;
        display.visible = !hint || hint->visible;
        display.transferFunction = hint && !hint->colours.empty()
                                       ? colourTableTransferFunction(hint->colours, low, high, defaultChannelOpacity)
                                       : colourWindowTransferFunction(channelColour(c), low, high, defaultChannelOpacity);
        displays.push_back(display);
    }
    return displays;
}

}  // namespace volren
