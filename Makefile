# Thin wrapper around CMake so the README's two commands stay short.
#   make run   install what the executable needs, build only qm-atms, analyse the bundled scene
#              (the one executable, build/cli/qm-atms)
#   make test  install every dependency, build everything (tests, benchmarks), run every test
# `make run` builds the one target the first answer needs (the laws in rules/ are read at run time,
# nothing to build); `make test` then builds the rest in the same tree, reusing what run built.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: deps deps-run configure configure-run build build-run run test clean

deps:
	bash cmake/install-deps.sh

deps-run:
	bash cmake/install-deps.sh run

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

configure-run: deps-run
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

build-run: configure-run
	cmake --build $(BUILD) -j $(JOBS) --target qm-atms

run: build-run
	./$(BUILD)/cli/qm-atms scenarios/alex/block.def

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD)
