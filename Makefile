# Thin wrapper: every target installs what is missing (tools/install-deps), configures and builds.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
ifdef CI
CMAKE_FLAGS += -DSTEPLAB_WERROR=ON
endif

.PHONY: all build test report bench test-sanitize clean deps

all: build

deps:
	@tools/install-deps build

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@tools/install-deps test
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

report: deps
	@tools/install-deps report
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target steplab
	@$(BUILD)/steplab report --out report

bench: build
	@$(BUILD)/steplab_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
	  --benchmark_out=$(BUILD)/bench.json --benchmark_out_format=json --ratios=$(BUILD)/bench-ratios.md
	@echo "wrote $(BUILD)/bench.json and $(BUILD)/bench-ratios.md"


clean:
	rm -rf $(BUILD)
