/* numfmt.h: locale-independent number formatting for SDL text.
 *
 * The writer formats millions of numbers per frame; printf is too slow for
 * that and depends on the locale (a de_DE locale writes 0,5). These
 * functions never look at the locale, never allocate and are thread-safe.
 */
#ifndef RGL_NUMFMT_H
#define RGL_NUMFMT_H

#include <stddef.h>
#include <stdint.h>

/* Longest output of numfmt_f32, without the NUL: a sign and 16 characters
 * of fixed notation ("-1073639350000000", "-0.00000123456789"), which is
 * used while at most three characters longer than scientific. */
#define NUMFMT_F32_MAX 17
/* Bytes numfmt_f32 may touch at out: it copies in fixed-size blocks for
 * speed; bytes past the returned length are scratch. */
#define NUMFMT_F32_ROOM 40

/* Writes the shortest decimal text that reads back (round to nearest) as
 * exactly v, e.g. 0.1f -> "0.1", 45 -> "45", 1e-7f -> "1e-07" is written
 * "1e-7". Fixed notation unless scientific is clearly shorter. -0 gives "0";
 * NaN and infinities give "0" (callers keep them out of SDL; this is the last
 * line of defence). out must have NUMFMT_F32_ROOM bytes; writes no NUL;
 * returns the length (<= NUMFMT_F32_MAX). */
size_t numfmt_f32(char *out, float v);

/* Decimal text of an unsigned or signed integer. Writes exactly the returned
 * number of bytes (at most 20 resp. 21), no NUL. */
size_t numfmt_u64(char *out, uint64_t v);
size_t numfmt_i64(char *out, int64_t v);

#endif
