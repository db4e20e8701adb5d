#include <volume_model/Histogram.h>

#include <algorithm>
#include <numeric>

namespace volren {

std::uint64_t Histogram::total() const
{
    return std::accumulate(counts.begin(), counts.end(), std::uint64_t(0));
}

double Histogram::binWidth() const
{
    return counts.empty() ? 0.0 : (maxValue - minValue) / double(counts.size());
}

double Histogram::binCentre(std::size_t i) const
{
    return minValue + (double(i) + 0.5) * binWidth();
}

double Histogram::percentile(double p) const
{
    const std::uint64_t n = total();
    if (n == 0) return minValue;
    const double target = std::clamp(p, 0.0, 1.0) * double(n);
    double seen = 0.0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        const double c = double(counts[i]);
        if (seen + c >= target && c > 0) {
            const double within = (target - seen) / c;  // linear inside the bin
            return minValue + (double(i) + within) * binWidth();
        }
        seen += c;
    }
    return maxValue;
}

double Histogram::otsuThreshold() const
{
    const double n = double(total());
    if (n == 0 || counts.size() < 2) return minValue;
    double sumAll = 0.0;
    for (std::size_t i = 0; i < counts.size(); ++i) sumAll += double(i) * double(counts[i]);
    double weightBack = 0.0, sumBack = 0.0, best = -1.0;
    std::size_t bestBin = 0;
    for (std::size_t i = 0; i + 1 < counts.size(); ++i) {
        weightBack += double(counts[i]);
        sumBack += double(i) * double(counts[i]);
        const double weightFore = n - weightBack;
        if (weightBack == 0 || weightFore == 0) continue;
        const double meanBack = sumBack / weightBack;
        const double meanFore = (sumAll - sumBack) / weightFore;
        const double between = weightBack * weightFore * (meanBack - meanFore) * (meanBack - meanFore);
        if (between > best) {
            best = between;
            bestBin = i;
        }
    }
    return minValue + double(bestBin + 1) * binWidth();
}

}  // namespace volren
