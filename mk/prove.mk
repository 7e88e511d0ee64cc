# Proofs over the C binding: Frama-C's EVA plug-in, one analysis per decoding and building entry
# point and per code path (prove/drivers, prove/README.md).
#
#   make prove        every analysis in prove/drivers, two at a time; fails if one has more alarms
#                     than its line allows (0, or the alarms still open, listed in prove/README.md)
#   make test-prove   the analyses that fit make test's time (PROVE_QUICK), one per entry point group
#
# Frama-C (frama-c-base) and the provers WP may use (z3, cvc4, why3) come from the system's
# packages, installed with apt when missing (tools/need).

PROVE_OUT := $(BUILD)/prove
# The analyses make test runs: the frame and payload parsers, the command decoder and the builders.
PROVE_QUICK ?= frame_parse command_decode payload_parse payload_build

TEST_TARGETS += test-prove

.PHONY: setup-prove prove test-prove

setup-prove:
	@command -v frama-c >/dev/null || tools/need --tool frama-c frama-c-base
	@command -v why3 >/dev/null && command -v z3 >/dev/null && command -v cvc4 >/dev/null \
		|| tools/need --tool why3 why3 z3 cvc4

prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT)

test-prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT)/quick $(PROVE_QUICK)
