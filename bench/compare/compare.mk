# make bench-compare: Blaze's CPU backend against LIGGGHTS 3.8.0 on the same scene, contact law
# and cores (bench/compare/README.md); installs LIGGGHTS through apt when run as root.
# Included by the Makefile after BUILD is set. BENCH_COMPARE_ARGS passes options to
# tools/bench_compare.sh (--help lists them), e.g. make bench-compare BENCH_COMPARE_ARGS="--side 16 --steps 300";
# the default appends the result to bench/results/compare-cpu.csv. LAW=hertz-history compares
# Hertz with the Mindlin spring against LIGGGHTS's hertz/history (bench/results/compare-cpu-hertz-history.csv).
BENCH_COMPARE_ARGS ?= --record
LAW ?= linear

.PHONY: bench-compare
bench-compare: $(BUILD)/cpu/blaze
	tools/bench_compare.sh --blaze $(BUILD)/cpu/blaze --law $(LAW) $(BENCH_COMPARE_ARGS)
