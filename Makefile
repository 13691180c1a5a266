# The two commands a new user runs: `make run` and `make test` (see README.md).
BUILD      ?= build
ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?=
JOBS       ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: setup configure build run test test-asan update-goldens fuzz bench gallery format clean

setup:
	@scripts/setup

configure: setup
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DINKSHADE_BUILD_BENCH=ON $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

run: build
	@scripts/demo $(BUILD)/inkshade out

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Warnings are errors in the Release build that `make test` and CI run; the sanitizer and clang
# (fuzz) builds optimise differently and report warnings without stopping.
test-asan: setup
	@cmake -S . -B $(ASAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DINKSHADE_SANITIZE=ON -DINKSHADE_WERROR=OFF -DINKSHADE_BUILD_BENCH=OFF -DINKSHADE_BUILD_PYTHON=OFF >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && ctest --output-on-failure -j $(JOBS)

# Rewrites the golden images tests/golden/STYLE--MODEL.png from the current renderer (only those
# whose pixels changed; goldens of removed styles go). Look at them, then commit (docs/testing.md).
update-goldens: build
	@MESA_SHADER_CACHE_DISABLE=true INKSHADE_UPDATE_GOLDENS=1 $(BUILD)/tests/inkshade_gl_tests --gtest_filter='Golden*' --gtest_brief=1

# libFuzzer targets (clang), each run FUZZ_SECONDS with its seed corpus (docs/testing.md#fuzzing).
fuzz:
	@scripts/setup --fuzz
	@cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DINKSHADE_WERROR=OFF -DINKSHADE_FUZZ=ON -DINKSHADE_BUILD_TESTS=OFF -DINKSHADE_BUILD_BENCH=OFF -DINKSHADE_BUILD_PYTHON=OFF >/dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzzers
	@scripts/fuzz $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

bench: build
	@scripts/bench $(BUILD)

gallery: build
	@scripts/setup --gallery
	@scripts/gallery $(BUILD)/inkshade docs/gallery

# Applies .clang-format to the project's C++ sources (clang-format 14 from Debian 12).
format:
	@command -v clang-format >/dev/null || apt-get install -y -q clang-format
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD) out
