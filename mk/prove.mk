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
# The analyses make test runs (about 2 minutes on 2 cores): the frame and payload parsers.
PROVE_QUICK ?= frame_parse payload_parse

# `make test-prove` (frame_parse and payload_parse on both builds' paths, ~1 minute plus the
# packages' install) is not yet in `make test`: the full suite is at its 30-minute bound; `make prove`
# runs every driver.

.PHONY: setup-prove prove test-prove

setup-prove:
	@command -v frama-c >/dev/null || tools/need --tool frama-c frama-c-base
	@command -v why3 >/dev/null && command -v z3 >/dev/null && command -v cvc4 >/dev/null \
		|| tools/need --tool why3 why3 z3 cvc4
	@test -f $$HOME/.why3.conf || why3 config detect >/dev/null

prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT)

test-prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT)/quick $(PROVE_QUICK)

# The WP proofs alone (prove/drivers: wp_frame, the frame check; wp_stream, the stream decoder).
.PHONY: prove-wp
prove-wp: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT) wp_frame wp_stream
