# Proofs over the C binding with Frama-C: EVA, one analysis per decoding and building entry point
# and per code path, and WP for the frame check and the stream decoder (prove/drivers,
# prove/README.md).
#
#   make prove        every line of prove/drivers, two at a time; fails if an analysis has an alarm
#                     or an unproved goal, or does not finish
#   make prove-wp     the WP lines alone
#   make test-prove   PROVE_QUICK, part of `make test`: every decoding and building entry point on
#                     the size path, the stream decoder's sentence recognition on both, and the two WP
#                     proofs replayed from prove/wp-cache (the provers' recorded results for the goals
#                     WP generates from the code as it is; a goal without one fails)
#
# `make test` runs the quick lines only: it is within a few minutes of its 30-minute bound, and the
# whole of `make prove` runs for longer than that (the $PAHR parse and the stream decoder set the
# pace: prove/README.md). `make prove` and `make prove-wp` run the provers and record their results
# in prove/wp-cache, to be committed with the change that altered the goals. Frama-C (frama-c-base)
# and the provers WP uses (z3, cvc4, why3) come from the system's packages, installed with apt
# when missing (tools/need).

PROVE_OUT := $(BUILD)/prove
# (They run in the order of prove/drivers, the longest first.)
PROVE_QUICK ?= wp_stream wp_frame pahr_parse frame_build payload_build pahr_build command_decode frame_parse \
	stream_sentence-quick stream_sentence-speed-quick payload_parse

TEST_TARGETS += test-prove

.PHONY: setup-prove prove test-prove

# Frama-C without the packages it recommends (why3 comes next; alt-ergo is not in the archive), then
# Why3 and the provers WP runs through it.
setup-prove:
	@command -v frama-c >/dev/null || tools/need --tool frama-c --no-recommends frama-c-base
	@command -v why3 >/dev/null && command -v z3 >/dev/null && command -v cvc4 >/dev/null \
		|| tools/need --tool why3 why3 z3 cvc4
	@test -f $$HOME/.why3.conf || why3 config detect >/dev/null

prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT)

test-prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	PROVE_WP_CACHE=replay prove/run.sh $(PROVE_OUT)/quick $(PROVE_QUICK)

# The WP proofs alone (prove/drivers: wp_frame, the frame check; wp_stream, the stream decoder).
.PHONY: prove-wp
prove-wp: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	prove/run.sh $(PROVE_OUT) wp_frame wp_stream
