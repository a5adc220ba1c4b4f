# lunaster — the two commands users and CI run: `make verify` and `make test`.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps build verify test test-mpi-full test-asan fuzz docs meshes clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)

# What `make verify` runs and nothing more: the launcher, the engine, the mesh generator and the
# PETSc module the decks load. The unit tests stay configured (LUNASTER_TESTS) and `make test`
# builds them.
VERIFY_TARGETS = lunaster lunaster-engine lunaster-meshgen lunaster_petsc
.PHONY: build-verify
build-verify: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS) --target $(VERIFY_TARGETS)

# Runs every deck of testcases/ and prints the TEST_RESU report; each deck gets 300 s and half of
# the machine's memory unless its header (-- lunaster: time_limit=S memory_limit=MB) says otherwise.
# The code_aster cases of testcases/comm/ carry code_aster's VALE_CALC: verify reports them against
# lunaster's values by default; their analytical VALE_REFE checks decide (--vale-calc=check counts them).
verify: build-verify
	$(BUILD)/lunaster verify testcases -j $(JOBS) --junit $(BUILD)/verify-junit.xml --json $(BUILD)/verify.json

# Unit tests (GoogleTest) and the deck suite under CTest; the MPI suites over testcases/ on their
# representative decks (tests/mpi/mpi_runs.py REPRESENTATIVE).
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE mpi_full

# The MPI suites' full matrix: every deck of testcases/ on 1, 2 and 3 ranks (CTest label mpi_full),
# after building the benchmark programs (tests/bench: no test runs them; built here so that CI
# compiles them).
test-mpi-full: build
	cmake --build $(BUILD) -j $(JOBS) --target benchmarks
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L mpi_full

# The whole suite under AddressSanitizer + UBSan. -O1 keeps the deck suite fast enough;
# leak checking stays on (detect_leaks=1; the MPI stack's own leaks are suppressed by tests/lsan.supp),
# any UBSan report fails the test. LUNASTER_SANITIZED tells the harness that memory budgets
# start from ASan's shadow memory. intercept_tls_get_addr=0: GCC 12's sanitizer runtime takes a
# dynamic TLS block whose address is 16 past a 4 KiB boundary for a glibc 2.19 header and reads a
# garbage range from it, and the leak checker's tracer then dies at exit (SIGSEGV) wherever the
# block happens to land (google/sanitizers#1322); seen on error/petsc_not_converged.lua, which
# passed or failed with the length of the working directory.
test-asan: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" -DLUNASTER_SANITIZE=ON $(CMAKE_FLAGS)
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:fast_unwind_on_malloc=0:intercept_tls_get_addr=0 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  LUNASTER_SANITIZED=1 ctest --output-on-failure -j $(JOBS) --timeout 1500 -LE mpi_full

# libFuzzer runs of the MED reader, the Gmsh reader and the deck front end (clang,
# ASan + UBSan), FUZZ_TIME seconds each, from the committed corpus tests/fuzz/corpus/.
# FUZZ_SEED=0 picks a random seed; .ci/run uses a fixed one.
FUZZ_TIME ?= 20
FUZZ_SEED ?= 0
fuzz:
	@bash scripts/install-deps.sh fuzz
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DLUNASTER_FUZZ=ON -DLUNASTER_TESTS=OFF $(CMAKE_FLAGS)
	cmake --build build-fuzz --target fuzzers -j $(JOBS)
	bash tests/fuzz/run_fuzzers.sh build-fuzz $(FUZZ_TIME) $(FUZZ_SEED)

docs: build
	$(BUILD)/lunaster --dump-catalog md docs/commands.md

# The speed/accuracy study (tests/bench/study, under 15 min on 2 cores): charts, CSV and the
# stability atlas under docs/study/. Needs matplotlib and CalculiX (install-deps.sh study).
# Never a pass/fail test. STUDY_FLAGS=--quick for a 2-minute smoke run, written to
# $(BUILD)/study/quick-docs/ so that it leaves the published docs/study/ alone.
study: build
	bash scripts/install-deps.sh study
	bash tests/bench/study/run_study.sh $(BUILD) $(STUDY_FLAGS)

meshes: build
	bash tools/make_meshes.sh $(BUILD)/lunaster-meshgen

clean:
	rm -rf $(BUILD) build-asan build-fuzz
