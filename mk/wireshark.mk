# Wireshark: the Lua dissector generated/wireshark/ilahrs.lua (generator/targets/wireshark), checked
# by tshark, which is installed from Debian's packages when missing.
#
#   make test-wireshark   the dissector against the Python binding on a recorded session (every
#                         command and payload table, calibrations, $PAHR, damaged bytes), two
#                         device variants, TCP; the pcapng writer against tshark; generated/docs/wireshark.md against
#                         the registered fields; a spec with one more command and payload table

WS_OUT := $(BUILD)/wireshark

.PHONY: setup-wireshark test-wireshark

setup-wireshark:
	@command -v tshark >/dev/null || tools/need tshark

test-wireshark: setup setup-wireshark
	$(PY) tests/wireshark/differential.py generated/wireshark/ilahrs.lua $(WS_OUT)
	$(PY) tests/wireshark/extended.py $(WS_OUT)/extended

TEST_TARGETS += test-wireshark
