# Thin wrapper: every target installs what is missing (tools/install-deps), configures and builds.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
ifdef CI
CMAKE_FLAGS += -DSTEPLAB_WERROR=ON
endif

.PHONY: all build test report bench bench-quick bench-debian-cvode performance test-sanitize test-sanitize-core fuzz clean deps

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

# `make bench`: every row, 5 repetitions (about 25 minutes on 2 cores); `make bench-quick`: the
# headline rows (a step on the spring beside Boost.Odeint and the hand-written loops, the rope at
# 4096 masses, the packs, CVODE's wrapper), 3 repetitions (about two minutes). Each writes
# build/bench.json and build/bench-ratios.md; the ratios file ends with CVODE as Debian builds it
# (no optimisation) against the build steplab uses: the same program, rope and steps
# (bench/cvode_rope.c). Google Benchmark's "Library was built as DEBUG" warning is about
# Debian's build of that library's own timing loop, not steplab's code (-O3): every row times
# batches of 10 000 steps (KeepRunningBatch: the step/, hand/, odeint/ and finite_check/ rows
# alike) or whole runs, so that loop's cost is negligible beside them. The ratios are of CPU
# times (the row's own thread's, which a busy core beside it hardly moves), the repetitions of
# all rows interleaved at random, and the load average recorded before and after.
BENCH_DEBUG_NOTE = (Google Benchmark's 'Library was built as DEBUG' warning concerns Debian's build of its timing loop, not steplab's -O3 code: the Makefile says why it does not matter)
BENCH_QUICK = ^((step|odeint|hand)/spring/|(hand/)?rope_size/(rk4|explicit_euler|implicit_euler)/4096$$|throughput|cvode_rope/)
bench: build
	@echo "make bench: every row, 5 repetitions, about 25 minutes (make bench-quick: the headline rows, about two minutes)"
	@echo "$(BENCH_DEBUG_NOTE)"
	@$(BUILD)/steplab_bench --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
	  --benchmark_out=$(BUILD)/bench.json --benchmark_out_format=json --ratios=$(BUILD)/bench-ratios.md
	@$(MAKE) --no-print-directory bench-debian-cvode
bench-quick: build
	@echo "make bench-quick: the headline rows, 3 repetitions, about two minutes"
	@echo "$(BENCH_DEBUG_NOTE)"
	@$(BUILD)/steplab_bench --benchmark_filter='$(BENCH_QUICK)' --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
	  --benchmark_report_aggregates_only=true --benchmark_out=$(BUILD)/bench.json --benchmark_out_format=json --ratios=$(BUILD)/bench-ratios.md
	@$(MAKE) --no-print-directory bench-debian-cvode
bench-debian-cvode:
	@if [ -x $(BUILD)/cvode_rope_debian ]; then \
	  o=$$($(BUILD)/cvode_rope 1024 1e-5 adams); d=$$($(BUILD)/cvode_rope_debian 1024 1e-5 adams); \
	  echo "$$o $$d" | awk '{ printf "CVODE Adams on the rope of 1024 masses, tol 1e-5, the same steps: Debian'"'"'s build (no -O) %.1f us a step, the optimised one %.1f us; Debian/optimised %.2f\n", 1e6*$$34/$$20, 1e6*$$16/$$2, ($$34/$$20)/($$16/$$2) }' \
	    | tee -a $(BUILD)/bench-ratios.md; fi
	@echo "wrote $(BUILD)/bench.json and $(BUILD)/bench-ratios.md"

# docs/performance.md, regenerated from measurements on this machine: `make bench`, then the
# studies whose figures it gives (about 4 minutes, and the maps), then tools/performance-md, which writes every
# figure from their JSON with its command and the machine.
MAP_METHODS = rk4,symplectic_euler,implicit_euler,implicit_midpoint,gauss_legendre4,radau_iia5,bdf2
performance: bench
	@mkdir -p $(BUILD)/performance
	@# the headline rows again, right after: how far a figure moves from run to run
	@$(BUILD)/steplab_bench --benchmark_filter='$(BENCH_QUICK)' --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
	  --benchmark_out=$(BUILD)/performance/bench-repeat.json --benchmark_out_format=json >/dev/null
	@$(BUILD)/steplab study scaling --sizes 1024 --error 1e-4 --json $(BUILD)/performance/scaling-rope.json >/dev/null
	@$(BUILD)/steplab study scaling --scene softbody --error 1e-4 --json $(BUILD)/performance/scaling-softbody.json >/dev/null
	@$(BUILD)/steplab study work-precision --json $(BUILD)/performance/work-precision.json >/dev/null
	@# the crossover maps (about an hour): tools/performance-md names these commands
	@$(BUILD)/steplab study scaling --scene rope --sizes 64,256,1024,4096 --stiffness 5,50,500,5000 --error 1e-4,1% \
	  --max-steps 500000 --methods $(MAP_METHODS),cvode_bdf_max2_band,radau5_band,arkode_ark548_band --json $(BUILD)/performance/scaling-map-rope.json >/dev/null
	@$(BUILD)/steplab study scaling --scene softbody --sizes 8,16,24,32 --stiffness 10,100,1000,10000 --error 1e-4,1% \
	  --max-steps 500000 --methods $(MAP_METHODS),cvode_bdf_max2_klu,radau5_wideband,arkode_ark548_klu --json $(BUILD)/performance/scaling-map-softbody.json >/dev/null
	@tools/performance-md --bench $(BUILD)/bench.json --repeat $(BUILD)/performance/bench-repeat.json --studies $(BUILD)/performance --out docs/performance.md

# The suite under AddressSanitizer and UndefinedBehaviorSanitizer, in its own build folder.
# Without -Werror: under the sanitizers GCC 12 reports -Wmaybe-uninitialized inside libstdc++
# (<regex>, std::function) that the normal build, which CI holds to -Werror, does not.
# A study runs 10-20x slower there, so a test that runs code again which another sanitized test
# already runs, to check a property of the numbers rather than of memory, runs in `make test` only
# (SANITIZE_SKIP; they were more than half the sanitized suite's time):
# - whole reports and studies with other parameters: ReportFindings, ReportGrowth, ReportChoice's
#   two, ReportInterrupted (with its up-to-date check), WorkPrecision's accuracy tests. Here a whole report is
#   made by ReportSheet (the hand-in, through the command line, gnuplot and pandoc), every
#   section by ReportChoice and ReportScenes, a work-precision study by WorkPrecision.CountsWhat...
# - the same bytes for one and two threads (Determinism, StabilityJson.SameForOneAndTwoThreads):
#   every study still runs here, split in parts and merged (Shards).
# - the allocation counts on the rope and the soft body of 64 and 4096 masses (Allocation.NoneInAStepOn...):
#   every method still steps every fixed-size scene here (Allocation.NoneInAnyStep...), and four
#   methods the rope through both its force interfaces (ScratchScenes).
# - package.plugin and readme.walkthrough (projects that instantiate the same templates on a new
#   method and scene; package.consumer still builds and links one against the sanitized package).
# - ReportSubsets (a whole report for each method alone and for pairs: ReportChoice's sections
#   and ReportSheet's whole report run here), ReportPages (the default report's page count and
#   figure text: the hand-in's are checked here).
# - Claims with other parameters (without damping, a stiff spring and a large step: the same
#   findings code as Claims.FollowTheDataWithDefaults, which runs here), and notebook.explore
#   (pandas reading the studies' JSON back; the studies that write it run here).
# - the long-time study's theory tests on the orbit (10^6-10^7 steps each; the same long-run code
#   runs here in LongTime's swinging-spring tests and in every method's check) and the report's
#   long-time sentences under two settings (ReportLongTime.HandIn... makes its section here); the
#   undamped rope's thresholds against the published constants (the mode-stability code runs here
#   on the damped rope and the chain), the energy drift against the stability functions (every
#   row's check runs here) and work-precision's counts against the formulas (the study runs here
#   in its one-and-two-threads test).
SANITIZE_SKIP ?= readme\.walkthrough|ReportPages|ReportGrowth|LongTime\.Kepler|ReportLongTime\.Follows|RopeStability\.Undamped|Check\.EnergyDrift|WorkPrecision\.CountsWhatTheFormulasSay|ReportSubsets|ReportChoice\.(AChosenMethodHasTheFullReportsNumbers|ACrossoverNeedsBothKinds)|ReportInterrupted|package\.plugin|ReportFindings|WorkPrecision\.(Rk4Accuracy|BdfSteps|AdaptiveErrors|ImplicitPays)|Determinism\.SameBytes|StabilityJson\.SameForOneAndTwoThreads|Allocation\.NoneInAStepOn|ReportSheet\.NumbersAreTheFullReports|Claims\.FollowTheData(WithoutDamping|WithAStiffSpringAndALargeStep)|notebook\.explore
test-sanitize: deps
	@tools/install-deps test
	@cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPLAB_SANITIZE=ON -DSTEPLAB_BUILD_BENCH=OFF -DSTEPLAB_WERROR=OFF >/dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	@cd $(BUILD)-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -E '$(SANITIZE_SKIP)'

# CI's sanitized stage: core/ and the tests of tests/core/ that need nothing else
# (tests/core_only.cmake), under AddressSanitizer and UndefinedBehaviorSanitizer, in a few minutes.
# The whole suite there (test-sanitize above) is about 40 minutes of compiling on 2 cores: each
# method's kernel file costs the compiler 4-5 times its Release time under the sanitizers.
test-sanitize-core: deps
	@tools/install-deps test
	@cmake -S . -B $(BUILD)-sanitize-core -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPLAB_SANITIZE=ON -DSTEPLAB_CORE_ONLY=ON -DSTEPLAB_WERROR=OFF >/dev/null
	@cmake --build $(BUILD)-sanitize-core -j $(JOBS)
	@cd $(BUILD)-sanitize-core && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

# libFuzzer over the command line and the report configuration, 60 s from tests/fuzz/corpus
# (new inputs go to $(BUILD)-fuzz/corpus; the kept corpus is not changed).
FUZZ_SECONDS ?= 60
fuzz:
	@tools/install-deps fuzz
	@CXX=clang++ cmake -S . -B $(BUILD)-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPLAB_FUZZ=ON -DSTEPLAB_BUILD_TESTS=OFF -DSTEPLAB_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD)-fuzz -j $(JOBS) --target steplab_fuzz
	@mkdir -p $(BUILD)-fuzz/corpus
	@$(BUILD)-fuzz/steplab_fuzz -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 -close_fd_mask=3 $(BUILD)-fuzz/corpus tests/fuzz/corpus

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(BUILD)-sanitize-core $(BUILD)-fuzz
