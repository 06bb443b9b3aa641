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

.PHONY: all deps build demo test test-farm test-sanitize fuzz-build fuzz fuzz-smoke bench validation-doc clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The demo: a soft bunny dropped next to a crate, 3 s at 30 fps, 1280x720.
demo: build
	$(BUILD)/recoil run assets/scenes/bunny-drop.json -o output/demo
	@echo "frames written to output/demo/"

# Builds what the suite runs (the CLI and the test executables), not the
# benchmarks: `make test` must stay well inside 10 minutes on 2 cores.
TEST_TARGETS = recoil recoil_tests_sim recoil_tests_render recoil_tests_cli recoil_tests_validation

test: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target $(TEST_TARGETS)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The render farm test (farm/README.md): a real single-node Slurm, started
# from the distribution's packages, runs a sharded `recoil batch` as a 3-task
# array and every item must come out exactly once. Needs root.
test-farm: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target recoil
	@bash scripts/install-deps.sh --farm
	bash farm/slurm/test-farm.sh $(BUILD)/recoil

# The suite under AddressSanitizer + UndefinedBehaviorSanitizer (run by CI).
# Left out: the long physics scenes, 2-10 min each under the sanitizers,
# whose code paths the shorter contact and world tests run as well.
SANITIZE_SKIP = AssimpCorpus|BunnyPileStaysWithinMargin|RollersPassTheBlockThrough|JellyStackStands|EveryShippedSceneRuns|FourRigidCubesStandTenSeconds|FourJellyCubesStandTenSeconds|DeformableBlockOnSlopeHolds|TheDrawnMeshRestsWithinTheMarginOfTheGround|AFineSurfaceFallingFreelyHasNoCandidates|SameSceneTwiceGivesIdenticalFramesAndStats|CappedSolveNeverReturnsWorseThanASolvedState|ASoftUFoldedShutDoesNotPassThroughItself|TheRollersExampleDrawsTheBallThroughTheGap|ASpiderCrushedByAHeavySphereKeepsItsElements
test-sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRECOIL_SANITIZE=ON -DRECOIL_BUILD_BENCH=OFF
	cmake --build build-asan -j $(JOBS) --target $(TEST_TARGETS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -E '$(SANITIZE_SKIP)'

# libFuzzer targets for the scene parser and the mesh, tet and PNG readers
# (fuzz/, docs/fuzzing.md), built with clang into their own folder and run one
# after another for FUZZ_SECONDS each; fails when any finds a crash. The smoke
# run replays FUZZ_RUNS fixed mutations of the committed seeds per target.
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 180
FUZZ_TARGETS ?= fuzz_scene fuzz_gmsh fuzz_tetgen fuzz_mesh_import fuzz_png

$(FUZZ_BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
	  -DCMAKE_CXX_COMPILER=clang++ -DRECOIL_FUZZ=ON -DRECOIL_BUILD_TESTS=OFF -DRECOIL_BUILD_BENCH=OFF

fuzz-build: deps $(FUZZ_BUILD)/CMakeCache.txt
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(FUZZ_TARGETS)

fuzz: fuzz-build
	bash fuzz/run.sh $(FUZZ_BUILD) seconds=$(FUZZ_SECONDS) $(FUZZ_TARGETS)

FUZZ_RUNS ?= 50000
fuzz-smoke: fuzz-build
	bash fuzz/run.sh $(FUZZ_BUILD) runs=$(FUZZ_RUNS) $(FUZZ_TARGETS)

# docs/performance.md from one run of every bench (`recoil_bench NAME` runs some, and writes no page).
bench: build
	$(BUILD)/recoil_bench > $(BUILD)/bench.md
	python3 scripts/performance_doc.py $(BUILD)/bench.md docs/performance.md
	@cat docs/performance.md

# docs/validation.md from what the validation suite measures (each test
# records its results); the page is written even when a check fails, and the
# target then fails with the suite.
validation-doc: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target recoil_tests_validation
	rm -f $(BUILD)/validation.json
	status=0; $(BUILD)/recoil_tests_validation --gtest_output=json:$(BUILD)/validation.json || status=$$?; \
	  python3 scripts/validation_doc.py $(BUILD)/validation.json docs/validation.md && exit $$status

clean:
	rm -rf $(BUILD) build-asan $(FUZZ_BUILD)
