/* stubgl.h: a stand-in for libGL, libGLU and libglut in the unit tests.
 *
 * stubgl.c defines every real function the recorder forwards to: those of
 * the AUTO and PRIM rows are generated from format/commands.def, the rest
 * are written by hand. Each logs its call (name, scalar arguments as
 * doubles, pointer arguments as given). Queries (glGet*) behave as GL with
 * no current context: they leave their output untouched.
 */
#ifndef RGL_TEST_STUBGL_H
#define RGL_TEST_STUBGL_H

#include <stdbool.h>
#include <stddef.h>

#include "format.h"

#define STUB_LOG_MAX 64

typedef struct stub_call {
    const char *name;
    unsigned nargs;
    double v[RGL_MAX_ARGS];      /* scalars */
    const void *p[RGL_MAX_ARGS]; /* pointers (NULL for scalars) */
} stub_call;

extern stub_call stub_log[STUB_LOG_MAX];
extern size_t stub_nlog;     /* calls logged since stub_reset (may pass MAX) */
extern int stub_glut_ready;  /* what glutGet(GLUT_INIT_STATE) returns */
extern GLint stub_render_mode_result; /* what glRenderMode returns */

void stub_reset(void);

/* Logs a call with no arguments (the generated stubs of the unrecorded
 * entry points, stub_unrecorded.c, log only their names). */
void stub_log_name(const char *name);

/* What the stub's glMapBuffer returns. */
extern unsigned char stub_mapped[4096];
/* glGetPolygonStipple answers the complement (0: GL's mask, all ones). */
extern unsigned char stub_pstipple_holes[128];

/* A context as far as the buffer queries go: glGetString(GL_VERSION)
 * returns stub_version (NULL: none), glGetIntegerv answers the pnames in
 * stub_ints, glGetBufferParameteriv stub_buffer_size and _mapped, and
 * glGetBufferSubData copies from stub_buffer. Everything else still acts
 * as GL without a context. */
typedef struct stub_int {
    unsigned pname;
    int value;
} stub_int;
extern const char *stub_version;
extern stub_int stub_ints[8];
extern size_t stub_nints;
extern unsigned char stub_buffer[4096];
extern int stub_buffer_size, stub_buffer_mapped;

#endif
