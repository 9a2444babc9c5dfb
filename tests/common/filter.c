/* Test machinery: not part of any assignment.
 * One test at a time: `make test-part3 FILTER=name` runs only the tests whose name matches
 * (cmocka's pattern: * and ? wildcards, e.g. FILTER='*hemisphere*'). The Makefile passes FILTER
 * as $PL_TEST_FILTER; this file is linked into every suite and applies it before main() runs, so
 * no suite's main() needs to know. */
#include "test.h"
#include <stdlib.h>

__attribute__((constructor)) static void filter_from_environment(void)
{
    const char *pattern = getenv("PL_TEST_FILTER");
    if (pattern && *pattern)
        cmocka_set_test_filter(pattern);
}
