# Thin wrapper over CMake: the README's two commands (`make demo`, `make test`)
# work from a clean clone; each installs missing system packages first.
BUILD ?= build
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?=
# New build folders use Ninja (installed by scripts/install-deps.sh): it
# compiles a target's sources while the libraries it links are still being
# built, which the Makefile generator does not. Clean `make test` on 2 cores:
# 4m19s of build with Ninja against about 7 min with Makefiles. CMake reads
# this only when it creates a build folder, so existing ones keep theirs.
export CMAKE_GENERATOR ?= Ninja

.PHONY: all deps build demo test test-sanitize bench clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The demo: a soft bunny dropped next to a crate, 3 s at 30 fps, 1280x720.
demo: build
	$(BUILD)/recoil run assets/scenes/bunny-drop.json -o output/bunny-drop
	@echo "frames written to output/bunny-drop/"

# Builds what the suite runs (the CLI and the test executables), not the
# benchmarks: `make test` must stay well inside 10 minutes on 2 cores.
TEST_TARGETS = recoil recoil_tests_sim recoil_tests_render recoil_tests_cli recoil_tests_validation

test: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target $(TEST_TARGETS)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The same suite under AddressSanitizer + UndefinedBehaviorSanitizer (CI's second step).
test-sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRECOIL_SANITIZE=ON -DRECOIL_BUILD_BENCH=OFF
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -E AssimpCorpus

bench: build
	$(BUILD)/recoil_bench

clean:
	rm -rf $(BUILD) build-asan
