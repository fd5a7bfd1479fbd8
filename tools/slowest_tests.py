#!/usr/bin/env python3
"""Where the suite's time goes: the slowest test cases and suites of a Boost.Test JUnit log.

make test writes BUILD/<backend>/junit.xml beside its usual output (RUN_TESTS in the Makefile);
this prints the suites by their total time and the slowest cases, so a case that makes CI slow is
seen in CI's own log (CI has 90 minutes on 2 cores; the brief asks for under 45).
Usage: tools/slowest_tests.py JUNIT_XML [N]      (N cases, default 15)
"""
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict


def main():
    path = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 15
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"slowest tests: no timings ({path}: {e})")
        return 0
    cases = []
    for tc in root.iter("testcase"):
        if tc.find("skipped") is not None:
            continue
        suite = tc.get("classname", "").split(".")[0]
        cases.append((float(tc.get("time", "0")), suite, tc.get("classname", "") + "/" + tc.get("name", "")))
    total = sum(t for t, _, _ in cases)
    by_suite = defaultdict(float)
    for t, suite, _ in cases:
        by_suite[suite] += t
    print(f"slowest tests: {len(cases)} cases ran in {total:.0f} s")
    suites = sorted(by_suite.items(), key=lambda kv: -kv[1])
    print("  suites: " + ", ".join(f"{s} {t:.0f} s" for s, t in suites[:n]))
    for t, _, name in sorted(cases, reverse=True)[:n]:
        print(f"  {t:8.1f} s  {name[:150]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
