#pragma once
/// One configuration of the speed–accuracy trade (`cairn bench trade`): what was turned, its error
/// against the case's oracle and its wall time; the Pareto front, the cheapest configuration
/// reaching an error, and trade.csv (written row by row, read back to resume).

#include <optional>
#include <string>
#include <vector>

namespace cairn::bench {

/// One measured configuration.
struct TradePoint {
    std::string case_name;         ///< "rocking", "rocking_slender", "impact"
    std::string backend;           ///< registry name
    std::string variant;           ///< backend-model/contact, e.g. "dem-rigid", "bullet-matched"
    std::string knobs;             ///< what was turned, "kn=3e9 dt_safety=0.1" (space-separated key=value)
    double kn = 0.0;               ///< contact stiffness of the scene, N/m³
    double dt = 0.0;               ///< time step used, s
    long long steps = 0;           ///< steps taken
    double sim_seconds = 0.0;      ///< simulated time, s
    double wall_seconds = 0.0;     ///< median wall time of the stepping loop over the repeats, s
    double error = 0.0;            ///< |relative error| of the case's checked metric(s); NaN = not measured
    std::string error_metric;      ///< which metric gave `error` ("first impact", "bounce period", ...)
    std::string status;            ///< "completed", "unstable", "refused", "failed", "no event"
    /// the resume key: case | variant | knobs
    std::string key() const;
    /// true when the error is a finite number from a completed run
    bool measured() const;
};

/// indices of the points on the Pareto front (no other point is both faster and more accurate),
/// over measured points only, by increasing wall time (and so decreasing error)
std::vector<size_t> pareto_front(const std::vector<TradePoint>& points);

/// the measured point of `variant` on `case_name` with the smallest wall time whose error is at
/// most `target` (a fraction: 0.01 = 1 %); none = it cannot
std::optional<size_t> cheapest_reaching(const std::vector<TradePoint>& points, const std::string& case_name,
                                        const std::string& variant, double target);

/// the measured point of `variant` on `case_name` with the smallest error (ties: the cheaper)
std::optional<size_t> most_accurate(const std::vector<TradePoint>& points, const std::string& case_name,
                                    const std::string& variant);

/// the header line of trade.csv
std::string trade_csv_header();
/// one row of trade.csv (no newline)
std::string trade_csv_row(const TradePoint& p);
/// every row of a trade.csv text; rows that do not parse (e.g. cut by an interruption) are skipped
std::vector<TradePoint> parse_trade_csv(const std::string& text);
/// read DIR/trade.csv if it exists (empty otherwise)
std::vector<TradePoint> read_trade_csv(const std::string& path);

}  // namespace cairn::bench
