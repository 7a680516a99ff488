#include "metrics/diff.hpp"

#include <cmath>

#include "metrics/signal.hpp"

namespace cairn::metrics {

double probe_path_rms(const std::vector<Sample>& a, const std::vector<Sample>& b, int p, double shift) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        Series sa, sb;
        for (const auto& x : a) { sa.t.push_back(x.t); sa.y.push_back(x.probes.at(p)[c]); }
        for (const auto& x : b) { sb.t.push_back(x.t); sb.y.push_back(x.probes.at(p)[c]); }
        double r = rms_difference(sa, sb, shift);
        sum += r * r;
    }
    return std::sqrt(sum);
}

}  // namespace cairn::metrics
