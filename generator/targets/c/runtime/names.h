/** 1 (the default): names and by-name lookups; 0: none (see "Build switches" above). */
#ifndef ILAHRS_NAMES
#define ILAHRS_NAMES 1
#endif
