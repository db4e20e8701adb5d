#include "BenchFront.h"

#include <algorithm>

namespace volren::app {

/// Pareto front per dataset, size and truth (rows drawing the same picture).
void markPareto(std::vector<BenchRow>& rows)
{
    for (BenchRow& p : rows) {
        if (p.renderer != "volren") continue;
        p.pareto = true;
        for (const BenchRow& q : rows) {
            if (&q == &p || q.renderer != "volren" || q.dataset != p.dataset || q.width != p.width ||
                q.height != p.height || q.truth != p.truth)
                continue;  // a different lighting model draws a different picture: not comparable
            const bool noWorse = q.frameMs <= p.frameMs && q.error.rmse <= p.error.rmse;
            const bool better = q.frameMs < p.frameMs || q.error.rmse < p.error.rmse;
            if (noWorse && better) {
                p.pareto = false;
                break;
            }
        }
    }
}

namespace {

/// Whether `a` beats `b`: better on one axis beyond the noise, and not worse beyond it on the
/// other: as accurate and faster beats (weak domination), as fast and more accurate does.
/// Images are deterministic: RMSE within 1 % is the same error.
bool beats(const BenchRow& a, const BenchRow& b)
{
    const double timeMargin = std::max(2.0 * (a.frameNoiseMs + b.frameNoiseMs), 0.02 * b.frameMs);
    const bool faster = a.frameMs < b.frameMs - timeMargin, notSlower = a.frameMs <= b.frameMs + timeMargin;
    const bool moreAccurate = a.error.rmse < 0.95 * b.error.rmse, asAccurate = a.error.rmse <= 1.01 * b.error.rmse;
    return (faster && asAccurate) || (moreAccurate && notSlower);
}

}  // namespace

std::vector<const BenchRow*> markRowsBeatingTheDefault(std::vector<BenchRow>& rows)
{
    std::vector<const BenchRow*> out;
    for (const BenchRow& d : rows) {
        if (d.renderer != "volren" || d.config != "default") continue;
        for (BenchRow& r : rows) {
            if (&r == &d || r.renderer != "volren" || r.dataset != d.dataset || r.width != d.width ||
                r.height != d.height || r.truth != d.truth)
                continue;
            r.beatsDefault = beats(r, d);
            r.beatenByDefault = beats(d, r);
            if (r.beatsDefault) out.push_back(&r);
        }
    }
    return out;
}

}  // namespace volren::app
