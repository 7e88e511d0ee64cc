# Proofs over the C binding with Frama-C: EVA, one analysis per decoding and building entry point
# and per code path, and WP for the frame check and the stream decoder (prove/drivers,
# prove/README.md). Every line of prove/drivers, two at a time, in about 5 minutes on 2 cores:
#
#   make prove        runs the provers on the WP goals that have no result in prove/wp-cache (the
#                     provers' recorded results, one per goal, named by the digest of the goal as
#                     WP generates it from the code as it is) and adds theirs, to be committed
#                     with the change that altered the goals; fails if an analysis has an alarm or
#                     an unproved goal, or does not finish
#   make prove-wp     the WP lines alone, the provers run on every goal, prove/wp-cache made to hold
#                     exactly their results (about 40 minutes)
#   make test-prove   part of `make test`: the same lines, each WP goal left to Z3 or CVC4 taking
#                     its result from prove/wp-cache (a goal without one fails)
#
# Frama-C (frama-c-base) and the provers WP uses (z3, cvc4, why3) come from the system's packages,
# installed with apt when missing (tools/need).

PROVE_OUT := $(BUILD)/prove

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
	PROVE_WP_CACHE=update prove/run.sh $(PROVE_OUT)

test-prove: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	PROVE_WP_CACHE=replay prove/run.sh $(PROVE_OUT)/test

# The WP proofs alone (prove/drivers: wp_frame, the frame check; wp_stream, the stream decoder).
.PHONY: prove-wp
prove-wp: setup-prove generated/c/ilahrs.c generated/c/ilahrs.h
	PROVE_WP_CACHE=record prove/run.sh $(PROVE_OUT) wp_frame wp_stream
