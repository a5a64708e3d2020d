/* tracegen.h: building small traces for the translator's tests.
 *
 * A seq collects encoded commands (rgl_cmd_encode); CMD(s, Name, values...)
 * appends command RGL_OP_Name with its arguments taken in order from the
 * values: one per scalar, `count` per fixed array, all the rest for a
 * counted array. trace_build wraps sequences into a whole trace with
 * rgl_trace_builder. Failures abort the test: these are test helpers.
 */
#ifndef RGL_TRACEGEN_H
#define RGL_TRACEGEN_H

#include <stddef.h>
#include <stdint.h>

#include "format.h"

typedef struct seq {
    uint8_t *data;
    size_t len, cap;
} seq;

void seq_init(seq *s);
void seq_free(seq *s);

/* Appends one command; str is the STR() argument of the rows that have one. */
void seq_cmd(seq *s, uint32_t opcode, const char *str, const double *v, size_t n);
/* The same with a BLOB (or STR) of nbytes bytes, which may hold zeros. */
void seq_cmd_bytes(seq *s, uint32_t opcode, const void *bytes, size_t nbytes, const double *v,
                   size_t n);

#define CMD(s, name, ...)                                                       \
    seq_cmd((s), RGL_OP_##name, NULL, (const double[]){__VA_ARGS__},            \
            sizeof((const double[]){__VA_ARGS__}) / sizeof(double))
#define CMD0(s, name) seq_cmd((s), RGL_OP_##name, NULL, NULL, 0)

/* rayglFrameBegin(name, loc, look, light). */
void seq_framebegin(seq *s, const char *name, const double v[9]);

/* A trace builder with helpers; frames and resources in call order. */
typedef struct trace {
    rgl_trace_builder *b;
    const uint8_t *data;
    size_t size;
} trace;

void trace_init(trace *t);
/* Adds a command resource (a state snapshot); returns its id. */
uint32_t trace_snapshot(trace *t, const seq *s);
void trace_frame(trace *t, uint32_t stream, uint32_t number, uint32_t flags, uint32_t state,
                 const seq *s);
/* Finishes (with an index) and sets t->data, t->size. */
void trace_finish(trace *t);
void trace_free(trace *t);

/* Writes bytes to a file; aborts on failure. */
void write_file(const char *path, const void *data, size_t size);

#endif
