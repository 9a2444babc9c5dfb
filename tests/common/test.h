/* Test machinery: not part of any assignment. One include for a test file: cmocka and our asserts. */
#ifndef PL_TEST_H
#define PL_TEST_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "check.h"

#endif
