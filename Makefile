# lunaster — the two commands users and CI run: `make verify` and `make test`.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps build verify test test-asan docs meshes clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)

# Runs every deck of testcases/ and prints the TEST_RESU report.
verify: build
	$(BUILD)/lunaster verify testcases -j $(JOBS) --junit $(BUILD)/verify-junit.xml --json $(BUILD)/verify.json

# Unit tests (GoogleTest) and the deck suite under CTest.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-asan: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DLUNASTER_SANITIZE=ON $(CMAKE_FLAGS)
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ctest --output-on-failure -j $(JOBS)

docs: build
	$(BUILD)/lunaster --dump-catalog md > docs/commands.md

meshes: build
	bash tools/make_meshes.sh $(BUILD)/lunaster-meshgen

clean:
	rm -rf $(BUILD) build-asan
