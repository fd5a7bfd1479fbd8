# Blaze: one source, two backends.
#   make run               default study (hopper discharge) on the GPU if there is one, else the CPU
#   make test              CPU verification suite (+ compile-only check of the CUDA build)
#   make test BACKEND=cuda verification suite on the GPU
#   make bench             particle-steps/s and per-phase times (GPU if present)
# Both install missing Debian packages first (tools/ensure_deps.sh).

BACKEND ?= cpu
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
# EIGEN_NO_CUDA: Eigen is host-only here (shape set-up, references), so it must not mark its
# functions __host__ __device__ under nvcc.
NVCCFLAGS := -std=c++17 -O3 -arch=$(CUDA_ARCH) -Werror cross-execution-space-call,all-warnings -DEIGEN_NO_CUDA \
             -Xcompiler -fopenmp,$(subst $(space),$(comma),$(WARN)) -Iinclude -I. -isystem /usr/include/eigen3 -DBLAZE_TEST_HEADER_ONLY
# The GPU machine has Boost headers but not its compiled libraries: CUDA builds use the header-only
# Boost.Test, and studies plot only where gnuplot-iostream was found at build time.
TEST_LIBS_cpu := -lboost_unit_test_framework
TEST_LIBS_cuda :=
PLOT_LIBS := $(if $(wildcard /usr/include/gnuplot-iostream.h),-lboost_iostreams -lboost_filesystem -lboost_system)

HEADERS := $(shell find include kernels verification studies bench -name '*.hpp')
TEST_SRC := $(wildcard verification/*.cpp)
STUDIES := $(notdir $(wildcard studies/*))

.PHONY: deps test run bench clean build-cpu build-cuda check-cuda figures
.DEFAULT_GOAL := run
.SECONDARY:

deps:
	@tools/ensure_deps.sh

# ---- objects: build/<backend>/<path>.o --------------------------------------------------------
build/cpu/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@
build/cuda/%.o: %.cpp $(HEADERS)
	@mkdir -p $(dir $@)
	$(NVCC) $(NVCCFLAGS) -x cu -c $< -o $@

build/cpu/blaze_tests: $(TEST_SRC:%.cpp=build/cpu/%.o)
	$(CXX) -fopenmp $^ -o $@ $(TEST_LIBS_cpu)
build/cuda/blaze_tests: $(TEST_SRC:%.cpp=build/cuda/%.o)
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@ $(TEST_LIBS_cuda)

build/cpu/study_%: build/cpu/studies/%/main.o
	$(CXX) -fopenmp $^ -o $@ $(PLOT_LIBS)
build/cuda/study_%: build/cuda/studies/%/main.o
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@ $(PLOT_LIBS)
build/cpu/blaze_bench: build/cpu/bench/bench.o
	$(CXX) -fopenmp $^ -o $@
build/cuda/blaze_bench: build/cuda/bench/bench.o
	$(NVCC) -arch=$(CUDA_ARCH) -Xcompiler -fopenmp $^ -o $@

build-cpu: build/cpu/blaze_tests $(STUDIES:%=build/cpu/study_%) build/cpu/blaze_bench
build-cuda: build/cuda/blaze_tests $(STUDIES:%=build/cuda/study_%) build/cuda/blaze_bench

# Compile (not run) the CUDA build so GPU code cannot rot unseen.
check-cuda:
ifeq ($(NVCC),)
	@echo "*** CUDA compile check SKIPPED: nvcc not found (install the CUDA toolkit to check the GPU build) ***"
else
	@$(MAKE) --no-print-directory -j$(NPROC) build-cuda
	@echo "CUDA build compiled for $(CUDA_ARCH) with $(NVCC)"
endif

ifeq ($(BACKEND),cuda)
test: deps
	@$(MAKE) --no-print-directory -j$(NPROC) build/cuda/blaze_tests
	OMP_NUM_THREADS=$(NPROC) build/cuda/blaze_tests --log_level=message --report_level=short --color_output=no
else
test: deps
	@$(MAKE) --no-print-directory -j$(NPROC) build-cpu
	@$(MAKE) --no-print-directory check-cuda
	build/cpu/blaze_tests --log_level=message --report_level=short --color_output=no
endif

# The main job: the default study on the GPU when one is present.
RUN_BACKEND := $(if $(and $(HAVE_GPU),$(NVCC)),cuda,cpu)
run: deps
	@echo "make run: backend = $(RUN_BACKEND) ($(if $(HAVE_GPU),GPU found,no GPU found: running on the CPU))"
	@$(MAKE) --no-print-directory -j$(NPROC) build/$(RUN_BACKEND)/study_hopper
	build/$(RUN_BACKEND)/study_hopper studies/hopper/hopper.params

bench: deps
	@$(MAKE) --no-print-directory -j$(NPROC) build/$(RUN_BACKEND)/blaze_bench
	build/$(RUN_BACKEND)/blaze_bench --out bench/results

clean:
	rm -rf build
