# Blaze: one source, two backends.
#   make run               default study (hopper discharge) on the GPU if there is one, else the CPU
#   make test              CPU verification suite (+ compile-only check of the CUDA build, + the MPI suite on 1-4 ranks)
#   make test BACKEND=cuda verification suite on the GPU
#   make bench             particle-steps/s and per-phase times (GPU if present)
#   make bench-compare     the CPU backend against LIGGGHTS on the same sphere scene, same cores
#   make table-3.3         the thesis's Table 3.3 (Cundall numbers) with Blaze's rows -> bench/table-3.3.md
#   make fig-3.24          one of the thesis's performance figures (fig-2.14, fig-3.21 ... fig-3.26)
#                          with our numbers -> plots/perf/; make perf-figures: all of them
#   make test SANITIZE=1   the CPU suite built with AddressSanitizer + UndefinedBehaviorSanitizer (in build-sanitize/)
#   make test POISON=1     the CPU suite with every buffer born as 0xFF bytes (in build-poison/)
#   make stress            the stress suite at full size (10^5 particles x 10^5 steps) and the cases CI trims; GPU if present
#   make fig-2.11          one thesis figure's verification case -> data/verification/, plots/fig-2.11.png
#   make figures           all of them; make verification-readme renders verification/README.md
#   make fig-repose        angle of repose, mu_s x mu_r (studies/repose; GPU if present); fig-repose-liggghts: LIGGGHTS side
#   make table-4.4         the thesis's lab-mill power table (studies/mill), two contact laws -> studies/mill/table-4.4.md
#   make fig-slice-mill    the slice mill's power and centrifuging layers against speed (studies/mill)
#   make fig-mill-2d       the 2D mill's toe and shoulder against friction (thesis 4.1.5; 2 h on 2 cores)
#   make los-bronces       the SAG mill of thesis 4.3: power per revolution and its split (GPU)
#   make mill-scaling      the thesis's 4e6-ball scaling mill (4.3.1): one revolution's wall time (GPU)
#   make fig-mill-work-precision  the lab mill's error against wall time over dt and precision
# Both install missing Debian packages first (tools/ensure_deps.sh).
# BUILD=dir builds elsewhere; TEST_SRC="verification/test_main.cpp verification/test_x.cpp" builds a subset.

BACKEND ?= cpu
SANITIZE ?=
POISON ?=
BUILD ?= $(if $(SANITIZE),build-sanitize,$(if $(POISON),build-poison,build))
NPROC := $(shell nproc 2>/dev/null || echo 2)
NVCC ?= $(shell command -v nvcc 2>/dev/null || ls /usr/local/cuda/bin/nvcc 2>/dev/null)
HAVE_GPU := $(shell nvidia-smi -L >/dev/null 2>&1 && echo yes)
CUDA_ARCH ?= sm_90

comma := ,
empty :=
space := $(empty) $(empty)
CXX := g++
WARN := -Wall -Wextra -Wshadow -Werror
CXXFLAGS := -std=c++17 -O2 -fopenmp $(WARN) -Iinclude -I. -isystem /usr/include/eigen3 -DBOOST_TEST_DYN_LINK
# SANITIZE=1: every error is fatal (no recovery), so a sanitizer finding fails the suite.
SAN_FLAGS := $(if $(SANITIZE),-fsanitize=address$(comma)undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
CXXFLAGS += $(SAN_FLAGS)
# POISON=1: host buffers start as 0xFF bytes (NaN, -1; exec/space.hpp), as stale GPU memory may
# be: a read before the first write fails the suite on the CPU too.
CXXFLAGS += $(if $(POISON),-DBLAZE_POISON_ALLOC)
LDFLAGS_cpu := -fopenmp $(SAN_FLAGS)
# EIGEN_NO_CUDA: Eigen is host-only here (shape set-up, references), so it must not mark its
# functions __host__ __device__ under nvcc.
# NVCC_OPT: nvcc's -O is the host side's optimisation (cicc and ptxas optimise device code either way).
NVCC_OPT ?= -O3
NVCCFLAGS := -std=c++17 $(NVCC_OPT) -arch=$(CUDA_ARCH) -Werror cross-execution-space-call,all-warnings -DEIGEN_NO_CUDA \
             -Xcompiler -fopenmp,$(subst $(space),$(comma),$(WARN)) -Iinclude -I. -isystem /usr/include/eigen3 -DBLAZE_TEST_HEADER_ONLY
# NVCC_EXTRA=-lineinfo: source lines for the profiler (ncu's source view); no change to the code.
# NVCC_EXTRA=-DBLAZE_FUSED_CLOCKS (profiling only, in its own BUILD=...): the small systems' one-block
# kernel counts each phase's cycles and each warp's share; blaze_bench's mill cases print them
# (include/blaze/exec/phases.hpp; bench/results/levers/small-mill-phases.md).
NVCCFLAGS += $(NVCC_EXTRA)
# The GPU machine has Boost headers but not its compiled libraries: CUDA builds use the header-only
# Boost.Test, and studies plot only where gnuplot-iostream was found at build time.
TEST_LIBS_cpu := -lboost_unit_test_framework -lgsl -lgslcblas
TEST_LIBS_cuda := -lgsl -lgslcblas
PLOT_LIBS := $(if $(wildcard /usr/include/gnuplot-iostream.h),-lboost_iostreams -lboost_filesystem -lboost_system)

HEADERS := $(shell find include kernels pipeline verification studies bench apps -name '*.hpp')
# Host-only sources, compiled by g++ for both backends (toml++ does not compile under nvcc).
HOST_OBJ := $(BUILD)/host/src/scene_toml.o
TEST_SRC ?= $(wildcard verification/*.cpp)
STUDIES := $(notdir $(patsubst %/main.cpp,%,$(wildcard studies/*/main.cpp)))  # folders with a driver (silo is run by study_hopper)

.PHONY: deps test run bench stress clean build-cpu build-cuda check-cuda figures verification-readme
.DEFAULT_GOAL := run
.SECONDARY:

deps:
	@tools/ensure_deps.sh

# ---- objects: build/<backend>/<path>.o --------------------------------------------------------
$(BUILD)/host/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@
$(BUILD)/cpu/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@
$(BUILD)/cuda/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(NVCC) $(NVCCFLAGS) -x cu -c $< -o $@

$(BUILD)/cpu/blaze_tests: $(TEST_SRC:%.cpp=$(BUILD)/cpu/%.o) $(HOST_OBJ)
	$(CXX) $(LDFLAGS_cpu) $^ -o $@ $(TEST_LIBS_cpu)
$(BUILD)/cuda/blaze_tests: $(TEST_SRC:%.cpp=$(BUILD)/cuda/%.o) $(HOST_OBJ)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@ $(TEST_LIBS_cuda)

# blaze run SCENE.toml: the general scene runner, one per backend.
# Its units: main.cpp and the law families' run_*.cpp (apps/blaze/run_scene.hpp), built in parallel.
BLAZE_SRC := $(wildcard apps/blaze/*.cpp)
$(BUILD)/cpu/blaze: $(BLAZE_SRC:%.cpp=$(BUILD)/cpu/%.o) $(HOST_OBJ)
	$(CXX) $(LDFLAGS_cpu) $^ -o $@
$(BUILD)/cuda/blaze: $(BLAZE_SRC:%.cpp=$(BUILD)/cuda/%.o) $(HOST_OBJ)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@

$(BUILD)/cpu/study_%: $(BUILD)/cpu/studies/%/main.o $(HOST_OBJ)
	$(CXX) $(LDFLAGS_cpu) $^ -o $@ $(PLOT_LIBS)
$(BUILD)/cuda/study_%: $(BUILD)/cuda/studies/%/main.o $(HOST_OBJ)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@ $(PLOT_LIBS)
# The MPI suite (issue 21: verification/mpi/, built with Open MPI's mpicxx and BLAZE_MPI=1; make
# test runs it on 1-4 ranks, oversubscribed, one OpenMP thread a rank; MPI's deprecated C++ bindings
# are left out: their headers do not pass -Werror).
MPICXX ?= $(shell command -v mpicxx 2>/dev/null)
MPI_TEST_SRC := $(wildcard verification/mpi/*.cpp)
MPIRUN := mpirun --oversubscribe $(if $(filter 0,$(shell id -u)),--allow-run-as-root)
MPI_RANKS ?= 1 2 3 4
$(BUILD)/mpi/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(MPICXX) $(CXXFLAGS) -DBLAZE_MPI=1 -DOMPI_SKIP_MPICXX=1 -DMPICH_SKIP_MPICXX=1 -c $< -o $@
$(BUILD)/mpi/blaze_mpi_tests: $(MPI_TEST_SRC:%.cpp=$(BUILD)/mpi/%.o) $(HOST_OBJ)
	$(MPICXX) $(LDFLAGS_cpu) $^ -o $@ -lboost_unit_test_framework
# blaze run over ranks (mpirun -np N build/mpi/blaze run SCENE.toml; apps/blaze/run_scene.hpp).
$(BUILD)/mpi/blaze: $(BLAZE_SRC:%.cpp=$(BUILD)/mpi/%.o) $(HOST_OBJ)
	$(MPICXX) $(LDFLAGS_cpu) $^ -o $@
# The mill and hopper studies over ranks (mpirun -np N build/mpi/study_mill SCENE.toml;
# studies/mill/mill_run.hpp, studies/hopper/hopper_run.hpp).
$(BUILD)/mpi/study_%: $(BUILD)/mpi/studies/%/main.o $(HOST_OBJ)
	$(MPICXX) $(LDFLAGS_cpu) $^ -o $@ $(PLOT_LIBS)
# The same suite on the CUDA backend (ranks sharing the GPUs; the GPU machine's header-only
# Boost.Test): MPI's flags from mpicxx, or MPI_DIR=<prefix with include/ and lib/>.
MPI_DIR ?=
MPI_INC ?= $(filter -I%,$(shell $(MPICXX) --showme:compile 2>/dev/null)) $(if $(MPI_DIR),-I$(MPI_DIR)/include)
MPI_LIB ?= $(filter -L% -l%,$(shell $(MPICXX) --showme:link 2>/dev/null)) $(if $(MPI_DIR),-L$(MPI_DIR)/lib -lmpi)
$(BUILD)/mpi-cuda/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(NVCC) $(NVCCFLAGS) -x cu -DBLAZE_MPI=1 -DOMPI_SKIP_MPICXX=1 -DMPICH_SKIP_MPICXX=1 $(MPI_INC) -c $< -o $@
$(BUILD)/mpi-cuda/blaze_mpi_tests: $(MPI_TEST_SRC:%.cpp=$(BUILD)/mpi-cuda/%.o) $(HOST_OBJ)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp,-pthread $^ -o $@ $(MPI_LIB)
# blaze run over ranks on the GPUs (mpirun -np N build/mpi-cuda/blaze run SCENE.toml).
$(BUILD)/mpi-cuda/blaze: $(BLAZE_SRC:%.cpp=$(BUILD)/mpi-cuda/%.o) $(HOST_OBJ)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp,-pthread $^ -o $@ $(MPI_LIB)
$(BUILD)/cpu/blaze_bench: $(BUILD)/cpu/bench/bench.o
	$(CXX) $(LDFLAGS_cpu) $^ -o $@
$(BUILD)/cuda/blaze_bench: $(BUILD)/cuda/bench/bench.o
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@

build-cpu: $(BUILD)/cpu/blaze_tests $(STUDIES:%=$(BUILD)/cpu/study_%) $(BUILD)/cpu/blaze_bench $(BUILD)/cpu/blaze $(BUILD)/mpi/blaze_mpi_tests $(BUILD)/mpi/apps/blaze/main.o $(BUILD)/mpi/study_mill $(BUILD)/mpi/study_hopper
build-cuda: $(BUILD)/cuda/blaze_tests $(STUDIES:%=$(BUILD)/cuda/study_%) $(BUILD)/cuda/blaze_bench $(BUILD)/cuda/blaze

# Compile (not run) the CUDA build so GPU code cannot rot unseen: every CUDA translation unit and
# link of build-cuda through nvcc's front end and cicc, the device code to PTX (CHECK_CUDA_ARCH:
# ptxas, the assembler to SASS, runs in the GPU machine's builds) and the host side unoptimised
# (CHECK_NVCC_OPT), in $(BUILD)/check-cuda so no GPU build ever takes these objects for its own:
# 46% of the full build's time on CI's two cores (studies/mill: 79 s against 172 s). cicc's own
# optimiser is off too (CHECK_NVCC_DEVICE_OPT): the front end, the device code generation and the
# host compile are what catch a rotten GPU build, and NVVM's -O3 was 70% of a unit's time
# (verification/test_cube_spin.cpp: 104 -> 42 s of CPU; the same 71 kernels in its PTX).
# CHECK_CUDA_ARCH=sm_90 CHECK_NVCC_OPT=-O3 CHECK_NVCC_DEVICE_OPT= checks the full build.
CHECK_CUDA_ARCH ?= compute_90
CHECK_NVCC_OPT ?= -O0
CHECK_NVCC_DEVICE_OPT ?= -Xcicc -O0
check-cuda: $(HOST_OBJ)
ifeq ($(NVCC),)
	@echo "*** CUDA compile check SKIPPED: nvcc not found (install the CUDA toolkit to check the GPU build) ***"
else
	@$(MAKE) --no-print-directory -j$(NPROC) BUILD=$(BUILD)/check-cuda HOST_OBJ=$(HOST_OBJ) \
	  CUDA_ARCH=$(CHECK_CUDA_ARCH) NVCC_OPT=$(CHECK_NVCC_OPT) NVCC_EXTRA="$(NVCC_EXTRA) $(CHECK_NVCC_DEVICE_OPT)" build-cuda
	@echo "CUDA build compiled for $(CHECK_CUDA_ARCH) (host $(CHECK_NVCC_OPT), device $(or $(CHECK_NVCC_DEVICE_OPT),optimised)) with $(NVCC) in $(BUILD)/check-cuda"
endif

# Each run writes the suite's table rows to $(BUILD)/<backend>/verification.tsv (report.hpp).
# TESTS=suite[/case][:...] runs a subset (Boost.Test --run_test syntax).
# Each case's time goes to $(BUILD)/<backend>/junit.xml; tools/slowest_tests.py prints where the
# suite's time went (after a failure too), so CI's log shows what makes it slow.
RUN_TESTS = rm -f $(BUILD)/$(1)/verification.tsv $(BUILD)/$(1)/junit.xml; status=0; BLAZE_REPORT=$(BUILD)/$(1)/verification.tsv \
  $(BUILD)/$(1)/blaze_tests --logger=HRF,message,stdout:JUNIT,error,$(BUILD)/$(1)/junit.xml --report_level=short \
  --color_output=no $(if $(TESTS),--run_test=$(TESTS)) || status=$$?; python3 tools/slowest_tests.py $(BUILD)/$(1)/junit.xml; exit $$status
# The MPI suite on each rank count of MPI_RANKS, its rows appended to the same table.
RUN_MPI_TESTS = set -e; for np in $(MPI_RANKS); do echo "MPI suite on $$np rank(s)"; \
  OMP_NUM_THREADS=1 BLAZE_REPORT=$(BUILD)/$(1)/verification.tsv $(MPIRUN) -np $$np $(BUILD)/mpi/blaze_mpi_tests \
  --log_level=message --report_level=short --color_output=no $(if $(TESTS),--run_test=$(TESTS)); done
ifeq ($(BACKEND),cuda)
test: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/cuda/blaze_tests $(BUILD)/cuda/blaze $(BUILD)/cuda/study_hopper
	export OMP_NUM_THREADS=$(NPROC); $(call RUN_TESTS,cuda)
else ifneq ($(SANITIZE)$(POISON),)
# Sanitized or poisoned: the suite and the blaze program it runs; no CUDA check (nvcc does not take
# these flags).
test: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/cpu/blaze_tests $(BUILD)/cpu/blaze $(BUILD)/cpu/study_hopper
	export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1; $(call RUN_TESTS,cpu)
else
test: deps
	@tools/check_layering.sh
	@python3 studies/silo/beverloo_fit.py --self-test
	@$(MAKE) --no-print-directory -j$(NPROC) build-cpu
	@$(MAKE) --no-print-directory check-cuda
	$(call RUN_TESTS,cpu)
	$(call RUN_MPI_TESTS,cpu)
endif

# The stress suite at full size (BLAZE_STRESS=full: 10^5 particles for 10^5 steps, a finer dt
# sweep), and the cases CI runs smaller (verification/stress_size.hpp): the issue's 10^4 elastic
# polyhedron collisions, Fig 3.27's settled share over six beds; on the GPU when there is one.
STRESS_TESTS := stress:polyhedron_dynamics/elastic_head_on_collisions_conserve_energy:contact_types/fig_3_27_edge_edge_fraction
stress: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/blaze_tests $(BUILD)/$(RUN_BACKEND)/blaze
	BLAZE_STRESS=full $(BUILD)/$(RUN_BACKEND)/blaze_tests --log_level=message --report_level=short --color_output=no \
	  --run_test=$(STRESS_TESTS)

# ---- thesis figures: plots/fig-X.gp names its verification cases on a "# test:" line ----------
FIGURE_DIR := data/verification
FIGURES := $(patsubst plots/%.gp,%,$(wildcard plots/fig-*.gp))
FIG_BACKEND := $(if $(filter cuda,$(BACKEND)),cuda,cpu)
.PHONY: $(FIGURES)
figures: $(FIGURES)
$(filter-out fig-work-precision,$(FIGURES)): deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(FIG_BACKEND)/blaze_tests
	@mkdir -p $(FIGURE_DIR)
	BLAZE_FIGURE_DIR=$(FIGURE_DIR) $(BUILD)/$(FIG_BACKEND)/blaze_tests --log_level=message --report_level=short \
	  --color_output=no --run_test=$$(sed -n 's/^# test: *//p' plots/$@.gp)
	gnuplot -e "datadir='$(FIGURE_DIR)'" plots/$@.gp
	@echo "wrote plots/$@.png"

# Error against wall time (studies/work_precision): writes verification/results/work_precision_<backend>.*
fig-work-precision: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(FIG_BACKEND)/study_work_precision
	$(BUILD)/$(FIG_BACKEND)/study_work_precision
	gnuplot plots/fig-work-precision.gp
	@echo "wrote plots/fig-work-precision.png"

# verification/README.md from the committed result tables (verification/results/*.tsv); a fresh
# CPU run's table replaces results/cpu.tsv when there is one.
verification-readme:
	@mkdir -p verification/results
	@if [ -s $(BUILD)/cpu/verification.tsv ]; then cp $(BUILD)/cpu/verification.tsv verification/results/cpu.tsv; fi
	python3 tools/verification_table.py verification/README.md.in verification/results/*.tsv > verification/README.md

# The main job: the default study on the GPU when one is present.
RUN_BACKEND := $(if $(and $(HAVE_GPU),$(NVCC)),cuda,cpu)
run: deps
	@echo "make run: backend = $(RUN_BACKEND) ($(if $(HAVE_GPU),GPU found,no GPU found: running on the CPU))"
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_hopper
	$(BUILD)/$(RUN_BACKEND)/study_hopper studies/hopper/hopper.toml

bench: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/blaze_bench
	$(BUILD)/$(RUN_BACKEND)/blaze_bench --out bench/results

# make bench-run: `blaze run` on a realistic scene (BENCH_RUN_SCENE, default 1,048,576 spheres
# falling into a packing; ~1 min on an H200, hours on 2 CPU cores) with and without its output,
# beside blaze_bench's dense bed at 1e6 (tools/bench_run.sh; a row in bench/results/).
BENCH_RUN_SCENE ?= bench/scenes/lattice_fall_1m.toml
.PHONY: bench-run
bench-run: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/blaze $(BUILD)/$(RUN_BACKEND)/blaze_bench
	tools/bench_run.sh $(BUILD)/$(RUN_BACKEND) $(BENCH_RUN_SCENE)

# Thesis Table 3.3 (Cundall numbers) with Blaze's rows from the committed GPU results.
.PHONY: table-3.3
table-3.3:
	python3 tools/table_3_3.py bench/results

# ---- the thesis's performance figures (issue 6): plots/perf/fig-X.gp over bench/results -------
# On a machine with a GPU the data are measured first (blaze_bench: falling, packed and largest
# polyhedron beds, the world-surface sweep; ~6 min on an H200, writes bench/results/<gpu>-<date>-
# figures.csv); elsewhere the committed GPU results are plotted. PERF_MEASURE=0 plots only.
PERF_FIGURES := $(patsubst plots/perf/%.gp,%,$(wildcard plots/perf/fig-*.gp))
PERF_MEASURE ?= $(if $(and $(HAVE_GPU),$(NVCC)),1,0)
.PHONY: perf-figures perf-data $(PERF_FIGURES)
perf-figures: $(PERF_FIGURES)
$(PERF_FIGURES): perf-data
	gnuplot plots/perf/$@.gp
	@echo "wrote plots/perf/$@.png"
perf-data: deps
ifeq ($(PERF_MEASURE),1)
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/cuda/blaze_bench
	$(BUILD)/cuda/blaze_bench --cases polyhedra,packed,surfaces,mesh --tag figures --out bench/results
	$(BUILD)/cuda/blaze_bench --cases largest --tag largest --out bench/results
else
	@echo "perf figures: no GPU here, plotting the committed GPU results in bench/results"
endif
	python3 tools/perf_figures.py

# ---- angle of repose (studies/repose): mu_s x mu_r sweep, GPU when present -------------------
# make fig-repose: the 3 x 3 sweep in Blaze -> REPOSE_DIR/<case>/, REPOSE_DIR/angles.csv,
# plots/fig-repose.png (small) or plots/fig-repose-full.png. REPOSE_SIZE=full (default with a GPU: ~18 000 beads on a base of 25 d)
# or small (default without: ~1 250 beads on 10 d, E = 1e7 Pa). make fig-repose-liggghts: the
# same piles in LIGGGHTS on the CPU (REPOSE_LIGGGHTS_CASES, mu_s:mu_r; at REPOSE_SIZE's size, into
# REPOSE_DIR beside Blaze's cases), their angles beside Blaze's.
REPOSE_SIZE ?= $(if $(and $(HAVE_GPU),$(NVCC)),full,small)
REPOSE_MU_S ?= 0.2 0.4 0.6
REPOSE_MU_R ?= 0 0.05 0.1
REPOSE_SETS_full :=
REPOSE_SETS_small := --set base_radius=10 --set hopper_width=16 --set orifice=7 --set particles=1100 --set end_time=2 \
  --set 'material[0].youngs_modulus=1e7' --set 'material[1].youngs_modulus=1e7'
REPOSE_SETS := $(REPOSE_SETS_$(REPOSE_SIZE))
# the small sweep's results in data/repose/ (beside LIGGGHTS's), the full one's in data/repose/full/
REPOSE_DIR := $(if $(filter full,$(REPOSE_SIZE)),data/repose/full,data/repose)
# the figure: REPOSE_DIR's angles, and make repose-scatter's other starts where they were run
REPOSE_PLOT = gnuplot -e "dir='$(REPOSE_DIR)'; size='$(REPOSE_SIZE)'; more='$(wildcard $(REPOSE_DIR)-gap*/angles.csv)'" plots/repose.gp
# cases at a time. 1 on a GPU as well: nine full-size piles sharing an H200 as nine processes
# (no MPS) ran 2.7x slower in total than one after another (the GPU switches between the
# processes' contexts; 2026-12-02: each reached t = 0.95 s in 575 s, alone a pile takes ~93 s;
# 2026-12-08 on an H100: 45-61 s a full-size pile, the nine in 8 minutes: tools/repose_device.sh).
REPOSE_JOBS ?= 1
REPOSE_LIGGGHTS_CASES ?= 0.2:0.05 0.4:0.05 0.6:0.05
# LIGGGHTS's MPI ranks per case (2026-12-08, full size on one core of an AMD EPYC: ~180 steps/s, ~40 min a pile)
REPOSE_LIGGGHTS_CORES ?= 1
.PHONY: fig-repose fig-repose-liggghts
fig-repose: deps
	@echo "fig-repose: backend = $(RUN_BACKEND), size = $(REPOSE_SIZE)"
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_repose
	tools/repose_sweep.sh $(BUILD)/$(RUN_BACKEND)/study_repose $(REPOSE_DIR) $(REPOSE_JOBS) "$(REPOSE_MU_S)" "$(REPOSE_MU_R)" \
	  -- $(REPOSE_SETS)
	$(REPOSE_PLOT)
	@echo "wrote $(REPOSE_DIR)/angles.csv, plots/fig-repose$(if $(filter full,$(REPOSE_SIZE)),-full).png"
fig-repose-liggghts: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/cpu/study_repose
	tools/repose_liggghts.sh --cores $(REPOSE_LIGGGHTS_CORES) --blaze $(BUILD)/cpu/study_repose --dir $(REPOSE_DIR) \
	  $(REPOSE_LIGGGHTS_CASES) -- $(REPOSE_SETS)
	$(REPOSE_PLOT)
	@echo "wrote $(REPOSE_DIR)/angles.csv, plots/fig-repose$(if $(filter full,$(REPOSE_SIZE)),-full).png"
# make repose-scatter: the same piles from other starts (the bcc fill's free gap, REPOSE_SCATTER_GAPS,
# instead of the scene's 0.05) for the cases near glass beads -> REPOSE_DIR-gap<digits>/ (0.02 ->
# -gap02); the plot shows them as crosses: the pile-to-pile scatter the angles are read with.
REPOSE_SCATTER_GAPS ?= 0.02 0.08
REPOSE_SCATTER_CASES ?= 0.4:0.05 0.4:0.1 0.6:0.05 0.6:0.1
.PHONY: repose-scatter
repose-scatter: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_repose
	@set -e; for g in $(REPOSE_SCATTER_GAPS); do for c in $(REPOSE_SCATTER_CASES); do \
	  tools/repose_sweep.sh $(BUILD)/$(RUN_BACKEND)/study_repose $(REPOSE_DIR)-gap$${g#0.} 1 $${c%%:*} $${c##*:} \
	    -- $(REPOSE_SETS) --set lattice_gap=$$g; done; done
	$(REPOSE_PLOT)

# ---- hopper discharge (studies/hopper) -------------------------------------------------------------
# make fig-2.15 / fig-2.16: the hopper of thesis section 2.5.3 with 2000 spheres and 2000 dodecahedra,
# poured by a feeder and discharged, three seeds each (HOPPER_SEEDS) -> data/hopper/pizette/,
# studies/hopper/pizette.md, plots/fig-2.15.png, plots/fig-2.16.png (tools/hopper_pizette.sh;
# a GPU target: on 2 CPU cores each dodecahedron run takes about an hour).
.PHONY: fig-2.15 fig-2.16
fig-2.15 fig-2.16: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_hopper
	tools/hopper_pizette.sh $(BUILD)/$(RUN_BACKEND)/study_hopper

# make fig-beverloo: glass beads poured into a flat-bottomed cylindrical silo read from STL files
# (studies/silo/make_silo_stl.py) and discharged through orifices of D/d = 5, 8, 11, 15 with
# Hertz-Mindlin; Beverloo's C and k fitted -> data/silo/beverloo/, studies/silo/beverloo.md,
# plots/fig-beverloo.png (tools/beverloo.sh; a GPU target: 70 000 beads per run).
.PHONY: fig-beverloo
fig-beverloo: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_hopper
	tools/beverloo.sh $(BUILD)/$(RUN_BACKEND)/study_hopper

# make fig-2.17: 13 824 corn kernels poured into a 60-degree hopper (an STL per orifice,
# studies/hopper/make_hopper_stl.py) and discharged through orifices of 2 to 4 kernel lengths, three
# seeds each: the runs that arch -> data/hopper/corn/, studies/hopper/corn.md, plots/fig-2.17.png
# (tools/corn_arching.sh; a GPU target; CORN_STOP_AFTER=seconds stops each run at a checkpoint, and
# the same command continues them).
.PHONY: fig-2.17
fig-2.17: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_hopper
	tools/corn_arching.sh $(BUILD)/$(RUN_BACKEND)/study_hopper

# ---- tumbling mills (studies/mill) ---------------------------------------------------------------
# make table-4.4: the thesis's Table 4.4 (3D lab mill: 20% and 30% filling, 14/22/32 rpm) with the
# history-free law and Hertz-Mindlin -> data/mill/table-4.4/, studies/mill/table-4.4.md,
# plots/fig-mill-power.png (tools/table_4_4.sh; ~10 minutes on 2 CPU cores).
# make fig-slice-mill: the slice mill of section 4.2.2 at 30-160% of critical speed -> data/mill/slice/,
# studies/mill/slice-mill.md, plots/fig-slice-mill.png (tools/slice_mill.sh; ~10 minutes on 2 cores).
# make fig-mill-2d: the 2D mill of section 4.1.5 (toe and shoulder against friction, Figures 4.3-4.4)
# -> data/mill/mill_2d/, studies/mill/mill-2d.md, plots/fig-mill-2d.png (tools/mill_2d.sh: five cases of
# 1.3e6 steps of 2916 balls, side by side one a core; ~1 h 45 min on 2 CPU cores).
# make fig-mill-work-precision: the 30% / 22 rpm lab mill's power and toe error against wall time
# for dt = t_c/10 ... t_c/100, float and double, two laws -> data/mill/work_precision/,
# studies/mill/work-precision.md, plots/fig-mill-work-precision.png (tools/mill_work_precision.sh).
# make los-bronces: the SAG mill of section 4.3 (139k spheres, 64 lifter rows, seven revolutions)
# -> data/mill/los_bronces/, studies/mill/los-bronces.md, plots/fig-los-bronces.png
# (tools/los_bronces.sh; a GPU target: 2.2e6 steps).
# make mill-scaling: the scaling mill of section 4.3.1 (4e6 balls, 28 m, one revolution)
# -> data/mill/scaling_mill/, studies/mill/scaling-mill.md (tools/scaling_mill.sh; a GPU target: 4e5 steps of 4e6 balls).
.PHONY: table-4.4 fig-slice-mill fig-mill-2d fig-mill-work-precision los-bronces mill-scaling
table-4.4: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/table_4_4.sh $(BUILD)/$(RUN_BACKEND)/study_mill
fig-slice-mill: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/slice_mill.sh $(BUILD)/$(RUN_BACKEND)/study_mill
los-bronces: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/los_bronces.sh $(BUILD)/$(RUN_BACKEND)/study_mill
mill-scaling: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/scaling_mill.sh $(BUILD)/$(RUN_BACKEND)/study_mill
fig-mill-2d: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/mill_2d.sh $(BUILD)/$(RUN_BACKEND)/study_mill
fig-mill-work-precision: deps
	@$(MAKE) --no-print-directory -j$(NPROC) $(BUILD)/$(RUN_BACKEND)/study_mill
	tools/mill_work_precision.sh $(BUILD)/$(RUN_BACKEND)/study_mill

# make bench-compare: the CPU backend against LIGGGHTS on the same scene (bench/compare/README.md).
include bench/compare/compare.mk

clean:
	rm -rf $(BUILD)
