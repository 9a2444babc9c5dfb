/* Test machinery: not part of any assignment. The growable-array helper (framework/buf.h). */
#include "../common/test.h"
#include <stdlib.h>
#include "../../framework/buf.h"
#include <stdint.h>

static void test_buf_append__keeps_every_element_in_order(void **state)
{
    (void)state;
    int *v = NULL, count = 0, cap = 0;
    for (int i = 0; i < 1000; i++) assert_int_equal(i, buf_append(&v, &count, &cap, sizeof i, &i));
    assert_int_equal(1000, count);
    assert_true(cap >= count);
    for (int i = 0; i < count; i++) assert_int_equal(i, v[i]);
    free(v);
}

static void test_buf_grow__refuses_sizes_that_overflow_and_changes_nothing(void **state)
{
    (void)state;
    char *keep = malloc(4);  /* from the heap, as every array buf_grow sees */
    assert_non_null(keep);
    int cap = 4;
    /* A count at INT_MAX cannot take one more; bytes past SIZE_MAX cannot be asked for. */
    assert_null(buf_grow(keep, INT_MAX, &cap, 1));
    assert_null(buf_grow(keep, 4, &cap, SIZE_MAX / 4));
    assert_int_equal(4, cap);
    /* With room to spare the array is returned as it is. */
    assert_ptr_equal(keep, buf_grow(keep, 3, &cap, 1));
    free(keep);
}

int buf_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_buf_append__keeps_every_element_in_order),
        cmocka_unit_test(test_buf_grow__refuses_sizes_that_overflow_and_changes_nothing),
    };
    return cmocka_run_group_tests_name("buf", tests, NULL, NULL);
}
