/* check.h: the translator tests' assertions: count failures, go on. */
#ifndef RGL_TR_CHECK_H
#define RGL_TR_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures;

#define CHECK(cond)                                                              \
    do {                                                                         \
        if (!(cond)) {                                                           \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            check_failures++;                                                    \
        }                                                                        \
    } while (0)

#define CHECK_NEAR(a, b, eps)                                                    \
    do {                                                                         \
        double a_ = (a), b_ = (b);                                               \
        if (!(fabs(a_ - b_) <= (eps))) {                                         \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %.9g (+-%g)\n", __FILE__, \
                    __LINE__, #a, a_, b_, (double)(eps));                        \
            check_failures++;                                                    \
        }                                                                        \
    } while (0)

#define CHECK_EQ_U(a, b)                                                         \
    do {                                                                         \
        unsigned long long a_ = (unsigned long long)(a), b_ = (unsigned long long)(b); \
        if (a_ != b_) {                                                          \
            fprintf(stderr, "%s:%d: %s = %llu, expected %llu\n", __FILE__, __LINE__, #a, \
                    a_, b_);                                                     \
            check_failures++;                                                    \
        }                                                                        \
    } while (0)

/* Exit status for meson: 0 when every check held. */
#define CHECK_RESULT(name)                                                       \
    (check_failures ? (fprintf(stderr, "%s: %d check(s) failed\n", name, check_failures), 1) \
                    : (printf("%s: all checks passed\n", name), 0))

#endif
