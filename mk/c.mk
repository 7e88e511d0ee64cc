# The C binding (generated/c/ilahrs.h + ilahrs.c, from generator/targets/c).
#
#   make build-c       library, conformance runner and example with gcc and clang, -Werror
#   make lint-c        the hand-written runtime against the committed clang-format style, the header
#                      compiled as C++ (g++ and clang++), the library with extra warnings
#   make test-c        unit tests under ASan+UBSan (gcc and clang, -O1 and -Os), the date codec against
#                      its old algorithm, the sanitized conformance runner
#                      (chunked and byte at a time, and the frames-only decoder against the full one),
#                      brief libFuzzer runs that must reach the build and round-trip functions
#                      (mk/fuzz.mk), CMake build, the example
#   make test-c-be     the same tests on a big-endian host (s390x under qemu-user)
#   make test-c-m4     the Cortex-M build's tests on an emulated Cortex-M4 (qemu-system-arm, MPS2 AN386)
#   make bench-c       stream decoder throughput next to a byte-summing loop, and its instructions per
#                      byte (valgrind's callgrind, -Os); writes build/bench/capture.bin
#   make footprint-c   Cortex-M4 code and RAM sizes (arm-none-eabi-gcc)
#   make fuzz-c        libFuzzer runs to a coverage plateau (mk/fuzz.mk)
#
# ilahrs.c is one code path: size or speed comes from the compiler's flags. The tests build it at -O1
# (sanitizers) and -Os (C_SIZE, as a Cortex-M firmware does), the benchmark at -O2.
#
# Tools missing on a fresh machine (clang, its libFuzzer runtime, cmake, arm-none-eabi-gcc, the
# s390x cross compiler, qemu-user, qemu-system-arm and valgrind) are installed with apt when needed.

C_DIR := generated/c
C_OUT := $(BUILD)/c
C_LIB := $(C_DIR)/ilahrs.c $(C_DIR)/ilahrs.h
C_STD := -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror
C_EXTRA := -Wcast-qual -Wstrict-prototypes -Wmissing-prototypes -Wold-style-definition -Wundef \
           -Wdouble-promotion -Wsign-conversion -Wswitch-enum -Wvla -Wredundant-decls -Wcast-align
C_SAN := -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
C_FUZZ := -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
C_SIZE := -Os
C_RUNTIME := generator/targets/c/runtime
CLANG_FORMAT := $(VENV)/bin/clang-format --style=file:generator/targets/c/.clang-format
CLANG ?= clang
FUZZ_RUNS ?= 150000
ARM_CC ?= arm-none-eabi-gcc
ARM_FLAGS := -std=c99 -mcpu=cortex-m4 -mthumb -Os -ffunction-sections -fdata-sections

SETUP_TARGETS += setup-c
BUILD_TARGETS += build-c
LINT_TARGETS += lint-c
TEST_TARGETS += test-c test-c-be test-c-m4
BENCH_TARGETS += bench-c
FOOTPRINT_TARGETS += footprint-c

.PHONY: setup-c build-c lint-c test-c test-c-be test-c-m4 bench-c footprint-c setup-c-arm setup-c-be setup-c-m4 \
        setup-c-valgrind

APT_INSTALL = tools/need $(1)

setup-c:
	@command -v $(CLANG) >/dev/null && command -v clang++ >/dev/null || $(call APT_INSTALL,clang)
	@printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' \
		| $(CLANG) -x c -fsanitize=fuzzer - -o /dev/null 2>/dev/null \
		|| $(call APT_INSTALL,libclang-rt-$$($(CLANG) -dumpversion | cut -d. -f1)-dev)
	@command -v cmake >/dev/null || $(call APT_INSTALL,cmake)

setup-c-arm:
	@command -v $(ARM_CC) >/dev/null || $(call APT_INSTALL,gcc-arm-none-eabi libnewlib-arm-none-eabi)

setup-c-valgrind:
	@command -v valgrind >/dev/null || $(call APT_INSTALL,valgrind)

# --- build: gcc and clang, -Werror --------------------------------------------------------

C_BINS := $(C_OUT)/ilahrs_conformance $(C_OUT)/clang/ilahrs_conformance \
          $(C_OUT)/decode_capture $(C_OUT)/clang/decode_capture

build-c: $(C_BINS)

$(C_OUT)/ilahrs_conformance: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) -O2 -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/clang/ilahrs_conformance: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) -O2 -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/decode_capture: $(C_DIR)/examples/decode_capture.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) -O2 -I$(C_DIR) $< $(C_DIR)/ilahrs.c -o $@

$(C_OUT)/clang/decode_capture: $(C_DIR)/examples/decode_capture.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) -O2 -I$(C_DIR) $< $(C_DIR)/ilahrs.c -o $@

# --- lint: the runtime's format, each runtime .c on its own, C++ use of the header, stricter -----
# warnings on the library. ilahrs.c holds the runtime's .c files after the tables, without the
# #include lines that open each: with them, each compiles on its own against ilahrs_internal.h (the
# tables) and the runtime files before it, as an editor compiles it (runtime/compile_flags.txt).
# Alone, a file leaves unused the helpers that files after it use: clang is told not to mind.

C_CXX := -std=c++11 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror

lint-c: setup-c $(C_LIB) $(C_DIR)/ilahrs_internal.h tests/c/cpp_check.cpp
	@mkdir -p $(C_OUT)/lint
	$(CLANG_FORMAT) --dry-run -Werror $(C_RUNTIME)/*.c $(C_RUNTIME)/*.h $(C_RUNTIME)/examples/*.c
	for f in $(filter-out %/examples,$(wildcard $(C_RUNTIME)/*.c)); do \
		gcc $(C_STD) $(C_EXTRA) -fsyntax-only -I$(C_DIR) $$f || exit 1; \
		gcc $(C_STD) $(C_EXTRA) -fsyntax-only -DILAHRS_NAMES=0 -I$(C_DIR) $$f || exit 1; \
		$(CLANG) $(C_STD) $(C_EXTRA) -Wno-unused-function -fsyntax-only -I$(C_DIR) $$f || exit 1; \
	done
	gcc $(C_STD) $(C_EXTRA) -O2 -c $(C_DIR)/ilahrs.c -o $(C_OUT)/lint/ilahrs.gcc.o
	$(CLANG) $(C_STD) $(C_EXTRA) -O2 -c $(C_DIR)/ilahrs.c -o $(C_OUT)/lint/ilahrs.clang.o
	g++ $(C_CXX) -I$(C_DIR) tests/c/cpp_check.cpp $(C_OUT)/lint/ilahrs.gcc.o -o $(C_OUT)/lint/cpp_check_gcc
	clang++ $(C_CXX) -I$(C_DIR) tests/c/cpp_check.cpp $(C_OUT)/lint/ilahrs.clang.o -o $(C_OUT)/lint/cpp_check_clang
	$(C_OUT)/lint/cpp_check_gcc
	$(C_OUT)/lint/cpp_check_clang
	gcc $(C_STD) $(C_EXTRA) -O2 -DILAHRS_NAMES=0 -c $(C_DIR)/ilahrs.c -o $(C_OUT)/lint/ilahrs_names_off.gcc.o
	$(CLANG) $(C_STD) $(C_EXTRA) $(C_SIZE) -DILAHRS_NAMES=0 -DILAHRS_STREAM_SENTENCES=0 \
		-c $(C_DIR)/ilahrs.c -o $(C_OUT)/lint/ilahrs_names_off.clang.o
	g++ $(C_CXX) -DILAHRS_NAMES=0 -I$(C_DIR) tests/c/cpp_check.cpp $(C_OUT)/lint/ilahrs_names_off.gcc.o \
		-o $(C_OUT)/lint/cpp_check_names_off
	$(C_OUT)/lint/cpp_check_names_off

# --- test ------------------------------------------------------------------------------------

$(C_OUT)/san/test_ilahrs_gcc: tests/c/test_ilahrs.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_SAN) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/san/test_ilahrs_clang: tests/c/test_ilahrs.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/san/ilahrs_conformance: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

# MemorySanitizer (clang): the stream tests start from ilahrs_stream_init(), the held bytes
# unwritten, so a decision on a held byte the decoder has not written fails the run; both code paths.
C_MSAN := -g -O1 -fsanitize=memory -fno-sanitize-recover=all -fno-omit-frame-pointer

$(C_OUT)/msan/test_ilahrs $(C_OUT)/msan/test_ilahrs_small: tests/c/test_ilahrs.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_MSAN) $(if $(findstring _small,$@),$(C_SIZE)) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

# The -Os build (as a Cortex-M firmware compiles ilahrs.c), tested on this host too.
$(C_OUT)/san/test_ilahrs_small: tests/c/test_ilahrs.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_SAN) $(C_SIZE) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/san/ilahrs_conformance_small: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) $(C_SIZE) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

# The frames-only stream decoder (ILAHRS_STREAM_SENTENCES=0), -O1 with clang and -Os with gcc:
# tests/c/frames_only.py checks it against the full decoder's vectors and captures.
C_FRAMES := -DILAHRS_STREAM_SENTENCES=0

$(C_OUT)/san/ilahrs_conformance_frames: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) $(C_FRAMES) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/san/ilahrs_conformance_frames_small: conformance/runners/c/conformance_runner.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_SAN) $(C_SIZE) $(C_FRAMES) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

# The library without name strings (ILAHRS_NAMES=0, header and ilahrs.c): tests/c/names_off.py checks
# that the names_off driver prints the same as in the default build, in pairs that differ in
# ILAHRS_NAMES only: gcc, and clang at -Os.
C_NAMES_OFF := $(C_OUT)/san/names_off $(C_OUT)/san/names_off_0 \
               $(C_OUT)/san/names_off_small $(C_OUT)/san/names_off_0_small

$(C_OUT)/san/names_off $(C_OUT)/san/names_off_0: tests/c/names_off.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_SAN) $(if $(findstring names_off_0,$@),-DILAHRS_NAMES=0) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_OUT)/san/names_off_small $(C_OUT)/san/names_off_0_small: tests/c/names_off.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) $(C_SIZE) $(if $(findstring names_off_0,$@),-DILAHRS_NAMES=0) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

test-c: $(C_NAMES_OFF)

# The integer helpers that take doubles against the double code they replace (test_values.c
# includes ilahrs.c): gcc, and clang at -Os.
$(C_OUT)/san/test_values $(C_OUT)/san/test_values_small: tests/c/test_values.c $(C_LIB)
	@mkdir -p $(@D)
	$(if $(findstring _small,$@),$(CLANG) $(C_SIZE),gcc) $(C_STD) $(C_SAN) -I$(C_DIR) $< -lm -o $@

# The date decoder and encoder against the code they replace (test_date.c includes ilahrs.c): every
# float of the date range at -O2 without sanitizers, a sample under sanitizers at -Os.
$(C_OUT)/test_date: tests/c/test_date.c $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) -O2 -I$(C_DIR) $< -o $@

$(C_OUT)/san/test_date_small: tests/c/test_date.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_SAN) $(C_SIZE) -I$(C_DIR) $< -o $@

$(C_OUT)/fuzz/%: fuzz/c/%.c $(C_LIB)
	@mkdir -p $(@D)
	$(CLANG) $(C_STD) $(C_FUZZ) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -o $@

$(C_OUT)/capture: bench/c/capture_main.c bench/c/capture.c bench/c/capture.h $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) -O2 -I$(C_DIR) -Ibench/c bench/c/capture_main.c bench/c/capture.c $(C_DIR)/ilahrs.c -o $@

# Seeds for the fuzzers: small captures built by the library (valid frames and sentences).
$(C_OUT)/corpus/.stamp: $(C_OUT)/capture
	@rm -rf $(C_OUT)/corpus && mkdir -p $(C_OUT)/corpus
	$(C_OUT)/capture --corpus $(C_OUT)/corpus --count 64 --size 512
	@touch $@

# A spec with one more command and one more payload table: the C target must pick them up with
# no template change (generated into build/, compiled warning-free, unit tests under sanitizers).
$(C_OUT)/extended/test_ilahrs: tests/c/extend_spec.py tests/c/test_ilahrs.c spec/ilahrs.yaml \
                               $(wildcard generator/*.py generator/targets/c/*.py generator/targets/c/templates/* $(C_RUNTIME)/*)
	@mkdir -p $(@D)
	$(PY) tests/c/extend_spec.py $(C_OUT)/extended/ilahrs.yaml
	$(PY) -m generator --spec $(C_OUT)/extended/ilahrs.yaml --out $(C_OUT)/extended/generated --target c >/dev/null
	gcc $(C_STD) $(C_SAN) -I$(C_OUT)/extended/generated/c tests/c/test_ilahrs.c $(C_OUT)/extended/generated/c/ilahrs.c -lm -o $@

C_FUZZERS := $(C_OUT)/fuzz/fuzz_stream $(C_OUT)/fuzz/fuzz_parsers

test-c: setup-c $(C_OUT)/san/test_ilahrs_gcc $(C_OUT)/san/test_ilahrs_clang $(C_OUT)/san/test_ilahrs_small \
        $(C_OUT)/msan/test_ilahrs $(C_OUT)/msan/test_ilahrs_small \
        $(C_OUT)/san/test_values $(C_OUT)/san/test_values_small $(C_OUT)/test_date $(C_OUT)/san/test_date_small \
        $(C_OUT)/san/ilahrs_conformance $(C_OUT)/san/ilahrs_conformance_small \
        $(C_OUT)/san/ilahrs_conformance_frames $(C_OUT)/san/ilahrs_conformance_frames_small \
        $(C_FUZZERS) $(C_OUT)/corpus/.stamp $(C_OUT)/capture $(C_OUT)/decode_capture $(C_OUT)/extended/test_ilahrs
	$(C_OUT)/san/test_ilahrs_gcc
	$(C_OUT)/san/test_ilahrs_clang 0x5EED
	$(C_OUT)/san/test_ilahrs_small 0xC0DE
	$(C_OUT)/msan/test_ilahrs 0xF00D
	$(C_OUT)/msan/test_ilahrs_small 0xBEEF
	$(C_OUT)/san/test_values
	$(C_OUT)/san/test_values_small 0xC0DE
	$(C_OUT)/test_date
	$(C_OUT)/san/test_date_small --sample 0xC0DE
	$(C_OUT)/extended/test_ilahrs
	$(PY) conformance/harness.py --command "$(C_OUT)/san/ilahrs_conformance" --name c-asan-ubsan
	$(PY) conformance/harness.py --command "$(C_OUT)/san/ilahrs_conformance --bytewise" --name c-bytewise
	$(PY) conformance/harness.py --command "$(C_OUT)/san/ilahrs_conformance_small" --name c-os
	$(PY) tests/c/differential.py $(C_OUT)/capture $(C_OUT)/san/ilahrs_conformance 16
	$(PY) tests/c/frames_only.py $(C_OUT)/capture $(C_OUT)/san/ilahrs_conformance_frames
	$(PY) tests/c/frames_only.py $(C_OUT)/capture "$(C_OUT)/san/ilahrs_conformance_frames_small --bytewise"
	C_STD="$(C_STD)" $(PY) tests/c/names_off.py $(C_OUT)/capture $(C_NAMES_OFF)
	$(PY) fuzz/run.py check c-fuzz_parsers c-fuzz_stream --runs $(FUZZ_RUNS) --corpus $(C_OUT)/corpus
	rm -rf $(C_OUT)/cmake && cmake -S $(C_DIR) -B $(C_OUT)/cmake -DILAHRS_BUILD_EXAMPLES=ON \
		-DCMAKE_C_FLAGS="$(C_STD)" -DCMAKE_INSTALL_PREFIX=$(ROOT)/$(C_OUT)/cmake/install >/dev/null
	cmake --build $(C_OUT)/cmake >/dev/null && cmake --install $(C_OUT)/cmake >/dev/null
	test -f $(C_OUT)/cmake/install/lib/pkgconfig/ilahrs.pc -o -f $(C_OUT)/cmake/install/lib64/pkgconfig/ilahrs.pc
	@# A user's project: find_package(ilahrs 1.0 REQUIRED) finds the installed package and builds against
	@# it; asking for a major version the package is not is refused.
	rm -rf $(C_OUT)/cmake-consumer && cmake -S tests/c/cmake_consumer -B $(C_OUT)/cmake-consumer \
		-DILAHRS_VERSION_WANTED=1.0 -DCMAKE_PREFIX_PATH=$(ROOT)/$(C_OUT)/cmake/install >/dev/null
	cmake --build $(C_OUT)/cmake-consumer >/dev/null && $(C_OUT)/cmake-consumer/consumer
	! cmake -S tests/c/cmake_consumer -B $(C_OUT)/cmake-consumer-2 -DILAHRS_VERSION_WANTED=2.0 \
		-DCMAKE_PREFIX_PATH=$(ROOT)/$(C_OUT)/cmake/install >/dev/null 2>&1
	rm -rf $(C_OUT)/cmake-names-off && cmake -S $(C_DIR) -B $(C_OUT)/cmake-names-off -DILAHRS_NAMES=OFF \
		-DCMAKE_C_FLAGS="$(C_STD)" -DCMAKE_INSTALL_PREFIX=$(ROOT)/$(C_OUT)/cmake-names-off/install >/dev/null
	cmake --build $(C_OUT)/cmake-names-off >/dev/null && cmake --install $(C_OUT)/cmake-names-off >/dev/null
	grep -q '^Cflags: .* -DILAHRS_NAMES=0$$' $(C_OUT)/cmake-names-off/install/lib*/pkgconfig/ilahrs.pc
	! nm $(C_OUT)/cmake-names-off/libilahrs.a | grep -q ilahrs_command_name
	$(C_OUT)/capture --size 200000 --seed 7 --out $(C_OUT)/example-capture.bin >/dev/null
	$(C_OUT)/decode_capture $(C_OUT)/example-capture.bin | tail -1

# --- big-endian host: s390x under qemu-user ---------------------------------------------------
# The library converts between wire and host order whatever the host's byte order: the unit
# tests, test_values and the conformance runner (-O2 and -Os, chunked and byte at a time) run on a
# big-endian s390x, statically linked and run by qemu-user.

BE_CC ?= s390x-linux-gnu-gcc
BE_RUN ?= qemu-s390x
C_BE := $(C_OUT)/be

setup-c-be:
	@command -v $(BE_CC) >/dev/null && command -v $(BE_RUN) >/dev/null \
		|| $(call APT_INSTALL,gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user)

$(C_BE)/test_ilahrs $(C_BE)/test_ilahrs_small: tests/c/test_ilahrs.c $(C_LIB) | setup-c-be
	@mkdir -p $(@D)
	$(BE_CC) $(C_STD) -O2 -static $(if $(findstring _small,$@),$(C_SIZE)) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_BE)/test_values: tests/c/test_values.c $(C_LIB) | setup-c-be
	@mkdir -p $(@D)
	$(BE_CC) $(C_STD) -O2 -static -I$(C_DIR) $< -lm -o $@

$(C_BE)/test_date: tests/c/test_date.c $(C_LIB) | setup-c-be
	@mkdir -p $(@D)
	$(BE_CC) $(C_STD) -O2 -static $(C_SIZE) -I$(C_DIR) $< -o $@

$(C_BE)/ilahrs_conformance $(C_BE)/ilahrs_conformance_small: conformance/runners/c/conformance_runner.c $(C_LIB) | setup-c-be
	@mkdir -p $(@D)
	$(BE_CC) $(C_STD) -O2 -static $(if $(findstring _small,$@),$(C_SIZE)) -I$(C_DIR) $< $(C_DIR)/ilahrs.c -lm -o $@

test-c-be: setup-c-be $(C_BE)/test_ilahrs $(C_BE)/test_ilahrs_small $(C_BE)/test_values $(C_BE)/test_date \
           $(C_BE)/ilahrs_conformance $(C_BE)/ilahrs_conformance_small $(C_OUT)/capture
	$(BE_RUN) $(C_BE)/test_ilahrs
	$(BE_RUN) $(C_BE)/test_ilahrs_small 0xC0DE
	$(BE_RUN) $(C_BE)/test_values
	$(BE_RUN) $(C_BE)/test_date --sample
	$(PY) conformance/harness.py --command "$(BE_RUN) $(C_BE)/ilahrs_conformance" --name c-s390x
	$(PY) conformance/harness.py --command "$(BE_RUN) $(C_BE)/ilahrs_conformance_small --bytewise" --name c-s390x-size-bytewise
	$(PY) tests/c/differential.py $(C_OUT)/capture "$(BE_RUN) $(C_BE)/ilahrs_conformance" 4

# --- Cortex-M4: the Cortex-M build on an emulated microcontroller -------------------------------
# The build `make footprint-c` measures (arm-none-eabi-gcc, $(ARM_FLAGS)), linked with newlib's
# semihosting runtime and run on qemu-system-arm's MPS2 AN386 board (a Cortex-M4, which faults on
# the unaligned multi-word accesses a desktop forgives): the unit tests, test_values, the date
# sample and the conformance runner (default and frames-only decoders, chunked and byte at a time).

M4_FLAGS := $(C_STD) $(ARM_FLAGS) --specs=rdimon.specs -T tests/c/m4/mps2-an386.ld -Wl,--gc-sections
M4_RUN := timeout 900 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
          -semihosting-config enable=on,target=native
C_M4 := $(C_OUT)/m4
M4_DEPS := tests/c/m4/startup.c tests/c/m4/mps2-an386.ld $(C_LIB)

setup-c-m4: setup-c-arm
	@command -v qemu-system-arm >/dev/null || $(call APT_INSTALL,qemu-system-arm)

$(C_M4)/test_ilahrs.elf: tests/c/test_ilahrs.c $(M4_DEPS) | setup-c-m4
	@mkdir -p $(@D)
	$(ARM_CC) $(M4_FLAGS) -I$(C_DIR) tests/c/m4/startup.c $< $(C_DIR)/ilahrs.c -lm -o $@

$(C_M4)/ilahrs_conformance.elf $(C_M4)/ilahrs_conformance_frames.elf: conformance/runners/c/conformance_runner.c $(M4_DEPS) | setup-c-m4
	@mkdir -p $(@D)
	$(ARM_CC) $(M4_FLAGS) $(if $(findstring _frames,$@),$(C_FRAMES)) -I$(C_DIR) tests/c/m4/startup.c $< \
		$(C_DIR)/ilahrs.c -lm -o $@

# test_values.c and test_date.c include ilahrs.c.
$(C_M4)/test_values.elf $(C_M4)/test_date.elf: $(C_M4)/%.elf: tests/c/%.c $(M4_DEPS) | setup-c-m4
	@mkdir -p $(@D)
	$(ARM_CC) $(M4_FLAGS) -I$(C_DIR) tests/c/m4/startup.c $< -lm -o $@

test-c-m4: setup-c-m4 $(C_M4)/test_ilahrs.elf $(C_M4)/test_values.elf $(C_M4)/test_date.elf \
           $(C_M4)/ilahrs_conformance.elf $(C_M4)/ilahrs_conformance_frames.elf $(C_OUT)/capture
	$(M4_RUN),arg=test_ilahrs,arg=0xC0DE -kernel $(C_M4)/test_ilahrs.elf
	$(M4_RUN),arg=test_values,arg=0xC0DE -kernel $(C_M4)/test_values.elf
	$(M4_RUN),arg=test_date,arg=--sample,arg=0xC0DE -kernel $(C_M4)/test_date.elf
	$(PY) conformance/harness.py --command "$(M4_RUN) -kernel $(C_M4)/ilahrs_conformance.elf" --name c-cortex-m4
	$(PY) conformance/harness.py --command "$(M4_RUN),arg=runner,arg=--bytewise -kernel $(C_M4)/ilahrs_conformance.elf" \
		--name c-cortex-m4-bytewise
	$(PY) tests/c/differential.py $(C_OUT)/capture "$(M4_RUN) -kernel $(C_M4)/ilahrs_conformance.elf" 4
	$(PY) tests/c/frames_only.py $(C_OUT)/capture "$(M4_RUN),arg=runner,arg=--bytewise -kernel $(C_M4)/ilahrs_conformance_frames.elf" 2

# --- bench, footprint ----------------------------------------------------------------

C_BENCH_OPT ?= -O2

$(C_OUT)/bench_stream: bench/c/bench_stream.c bench/c/capture.c bench/c/capture.h $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_BENCH_OPT) -DBENCH_BUILD='"gcc $(C_BENCH_OPT)"' -I$(C_DIR) -Ibench/c \
		bench/c/bench_stream.c bench/c/capture.c $(C_DIR)/ilahrs.c -o $@

# build/bench/capture.bin is the same capture bench_stream builds in memory (64 MiB, seed 1), for
# other bindings' benchmarks; capture.txt says what the C decoder finds in it.
# count_stream: the decoder built as a Cortex-M firmware builds it (-Os, no sanitizer), its
# instructions per byte on 1 MiB of the capture counted by callgrind, fed whole and a byte at a time.
$(C_OUT)/count_stream: bench/c/count_stream.c bench/c/capture.c bench/c/capture.h $(C_LIB)
	@mkdir -p $(@D)
	gcc $(C_STD) $(C_SIZE) -I$(C_DIR) -Ibench/c bench/c/count_stream.c bench/c/capture.c $(C_DIR)/ilahrs.c -o $@

bench-c: setup-c-valgrind $(C_OUT)/bench_stream $(C_OUT)/capture $(C_OUT)/count_stream
	@mkdir -p $(BUILD)/bench
	$(C_OUT)/capture --out $(BUILD)/bench/capture.bin | tee $(BUILD)/bench/capture.txt
	$(C_OUT)/bench_stream
	$(PY) bench/c/count_stream.py $(C_OUT)/count_stream --out $(C_OUT)/callgrind --build "gcc $(C_SIZE)"

footprint-c: setup-c-arm
	@mkdir -p $(C_OUT)/footprint
	$(PY) bench/c/footprint.py --cc $(ARM_CC) --flags "$(ARM_FLAGS)" --source $(C_DIR)/ilahrs.c \
		--include $(C_DIR) --out $(C_OUT)/footprint
