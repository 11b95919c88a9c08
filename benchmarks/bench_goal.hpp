// A benchmark's goals and checks, held and not only printed.
//
// A check (require(): the peer's result agrees with towgeom's, the expected loops, the program's
// exit status) must hold in every run; a peer whose result disagrees gives no ratio worth
// comparing, so each benchmark checks its peer before it takes one. A goal (ratioAtLeast(),
// secondsAtMost()) is a speed target: a full run (the README's commands, at the benchmark's
// default size) holds it; a smoke run (--smoke: the CTest runs at small sizes on shared machines,
// where timings say nothing about the goal) only requires it to have been measured, finite and
// positive. Every goal and check is printed with its verdict, whatever the others gave, and
// summed up at the end. Exit status (exitStatus()):
//   0  every check held and every goal was met (or, with --smoke, measured);
//   1  a check failed or a goal could not be measured (the run is wrong, whatever its speed);
//   3  every check held but a goal was MISSED (the run is right, only slower than its target).
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
        measured(what, ratio, "ratio", ratio >= minimum, "x, goal >= " + number(minimum) + "x");
    }

    /// @p seconds of towgeom's; the goal is seconds <= @p maximum.
    void secondsAtMost(const std::string& what, double seconds, double maximum)
    {
        measured(what, seconds, "time", seconds <= maximum, " s, goal <= " + number(maximum) + " s");
    }

    /// A count (or any positive figure) whose goal is at most @p maximum.
    void atMost(const std::string& what, double value, double maximum, const std::string& unit = "")
    {
        measured(what, value, "value", value <= maximum, unit + ", goal <= " + number(maximum) + unit);
    }

    /// A correctness check: must hold in every run. Returns @p ok.
    bool require(const std::string& what, bool ok)
    {
        ++checks_;
        if (!ok) ++failed_;
        std::printf("check %s: %s\n", what.c_str(), ok ? "held" : "FAILED");
        return ok;
    }

    /// 0, 1 or 3 as the file's header says, after a one-line summary.
    int exitStatus() const
    {
        std::printf("summary: %d check(s), %d failed; %d goal(s), %d met, %d MISSED, %d not measured%s\n", checks_,
                    failed_, goals_, met_, missed_, unmeasured_, smoke_ ? " (smoke run: goals measured, not held)" : "");
        if (failed_ || unmeasured_) return 1;
        return missed_ ? 3 : 0;
    }

private:
    static std::string number(double x)
    {
        char s[32];
        std::snprintf(s, sizeof s, "%g", x);
        return s;
    }

    void measured(const std::string& what, double value, const char* kind, bool met, const std::string& unitAndGoal)
    {
        ++goals_;
        const bool valid = std::isfinite(value) && value > 0.0;
        const char* verdict = !valid ? "FAILED (not measured)" : smoke_ ? "not held (--smoke)" : met ? "met" : "MISSED";
        std::printf("goal %s: %s %.3g%s: %s\n", what.c_str(), kind, value, unitAndGoal.c_str(), verdict);
        if (!valid)
            ++unmeasured_;
        else if (!smoke_)
            ++(met ? met_ : missed_);
    }

    bool smoke_;
    int checks_ = 0, failed_ = 0, goals_ = 0, met_ = 0, missed_ = 0, unmeasured_ = 0;
};

}  // namespace towgeom::bench
