// A benchmark's goals, checked and not only printed. A full run (the README's commands, at the
// benchmark's default size) exits 1 when a goal is missed. A smoke run (--smoke: the CTest runs at
// small sizes on shared machines, where timings say nothing about the goal) does not hold the
// timing to its goal, but the measurement must still have been made: the ratio to the peer or
// the time computed, finite and positive. Correctness checks (same results as the peer, the
// expected loops) apply to both.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace towgeom::bench {

class Goals {
public:
    explicit Goals(bool smoke) : smoke_(smoke) {}

    /// @p ratio = the peer's time / towgeom's time; the goal is ratio >= @p minimum.
    void ratioAtLeast(const std::string& what, double ratio, double minimum)
    {
        measured(what, ratio, "ratio", [&] { return ratio >= minimum; }, "x, goal >= " + number(minimum) + "x");
    }

    /// @p seconds of towgeom's; the goal is seconds <= @p maximum.
    void secondsAtMost(const std::string& what, double seconds, double maximum)
    {
        measured(what, seconds, "time", [&] { return seconds <= maximum; }, " s, goal <= " + number(maximum) + " s");
    }

    /// A correctness check: must hold in every run.
    void require(const std::string& what, bool ok)
    {
        if (!ok) {
            ++failed_;
            std::printf("check %s: FAILED\n", what.c_str());
        }
    }

    /// 0 when every goal was met (or, with --smoke, measured) and every check held; else 1.
    int exitStatus() const
    {
        if (failed_) std::printf("%d goal(s) or check(s) failed%s\n", failed_, smoke_ ? " (smoke run)" : "");
        return failed_ ? 1 : 0;
    }

private:
    static std::string number(double x)
    {
        char s[32];
        std::snprintf(s, sizeof s, "%g", x);
        return s;
    }

    template <class Met>
    void measured(const std::string& what, double value, const char* kind, Met met, const std::string& unitAndGoal)
    {
        const bool valid = std::isfinite(value) && value > 0.0;
        const char* verdict = !valid ? "FAILED (not measured)" : smoke_ ? "not checked (--smoke)" : met() ? "met" : "MISSED";
        std::printf("goal %s: %s %.3g%s: %s\n", what.c_str(), kind, value, unitAndGoal.c_str(), verdict);
        if (!valid || (!smoke_ && !met())) ++failed_;
    }

    bool smoke_;
    int failed_ = 0;
};

}  // namespace towgeom::bench
