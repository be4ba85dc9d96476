# SPDX-License-Identifier: Apache-2.0
# The two commands of the README, and a few conveniences. Everything real lives in
# CMakePresets.json and scripts/; this file only strings them together.
#   make demo   install what the demo needs, build the tools (not the tests), run the default example
#   make test   install what is missing, build, run the whole test suite (ctest)
#   make test-asan   the unit and CLI suites again under ASan + UBSan (CI runs both)
#   make install   install the build under PREFIX (default /usr/local; docs/install.md)
#   make package   the .deb (cpack -G DEB) in build/<preset>/
# PRESET=debug or PRESET=asan selects another build (default: release).

PRESET ?= release
BUILD_DIR := build/$(PRESET)
PREFIX ?= /usr/local

.PHONY: all deps configure build test test-asan demo bench clean format install package

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build --preset $(PRESET)

test: build
	@ctest --preset $(PRESET)

# The unit, integration and CLI suites under AddressSanitizer + UndefinedBehaviorSanitizer (CI
# runs it after `make test`; docs/testing.md).
test-asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan
	@ctest --preset asan-ci

# The demo needs neither the test suite nor its oracles: the `demo` preset builds the five
# tools it runs (and the image module) into build/release, which `make test` then completes
# (docs/install.md).
demo:
	@scripts/install-deps.sh --demo
	@cmake --preset demo >/dev/null
	@cmake --build --preset demo
	@examples/demo/run.sh build/release/bin out/demo

install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX)

package: build
	@cd $(BUILD_DIR) && cpack -G DEB

bench: build
	@bench/run.sh $(BUILD_DIR)/bin

clean:
	rm -rf build out

format:
	@git ls-files '*.cpp' '*.h' | xargs clang-format -i
