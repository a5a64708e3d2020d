/* unrecorded.h: counting the calls RayGL forwards without recording.
 *
 * Every entry point of GL 1.0-2.1, GLU 1.3 and freeglut that is neither a
 * row of commands.def nor a query has a generated twin
 * (entry_unrecorded.c, tools/gen_unrecorded.py) that counts the call in
 * the calling thread's stream, then makes the real call. The counts go
 * into the trace at the frame's end as @NotRecorded(name, count) commands,
 * so the translator can say what the trace lacks. Counting costs an
 * increment: no lock, no system call, no encoding.
 */
#ifndef RGL_UNRECORDED_H
#define RGL_UNRECORDED_H

#include "recorder.h"

/* The generated table: how many unrecorded entry points, and their names,
 * sorted (strcmp order); an id is an index into it. Ids live only in
 * memory: the trace stores names. */
extern const unsigned rgl_unrecorded_total;
extern const char *const rgl_unrecorded_names[];

/* The slow path of rgl_unrecorded_count: creates the thread's stream
 * (without opening the trace: a program that records nothing leaves no
 * file) and counts there;
 * counts nothing while not recording or inside a recorded GLU or GLUT call
 * (the preload's passthrough). */
void rgl_unrecorded_slow(unsigned id);

/* Counts one call of unrecorded entry point `id` on the calling thread. */
static inline void rgl_unrecorded_count(unsigned id)
{
    rgl_stream *s = rgl_tls_stream;
    if (RGL_LIKELY(s != NULL && s->unrecorded != NULL && rgl_tls_passthrough == 0))
        s->unrecorded[id]++;
    else
        rgl_unrecorded_slow(id);
}

/* Counts one call of unrecorded entry point `id`, whose one argument
 * `value` sets the GL state `pname` (format/unrecorded.def's STATE column),
 * unless GL's current value already equals it: such a call changes
 * nothing. GL is asked only with a live context, outside glBegin/glEnd and
 * the passthrough; otherwise the call is counted. */
void rgl_unrecorded_count_state(unsigned id, unsigned pname, int value);

/* GLUT's text (gluttext.c): the twins of glutBitmapCharacter,
 * glutBitmapString, glutStrokeCharacter and glutStrokeString call the real
 * function between these, so that freeglut's own gl* calls are recorded.
 * rgl_glut_text_enter returns 1 when they will be (libraygl, libglut's
 * slots hooked), else 0 (the twin counts the call then); pass its result
 * to rgl_glut_text_leave. Calling thread only. */
int rgl_glut_text_enter(void);
void rgl_glut_text_leave(int entered);

/* The gl* names freeglut draws text with, and their hooks (libraygl). */
#define RGL_GLUT_TEXT_HOOKS 8
extern const char *const rgl_glut_text_names[RGL_GLUT_TEXT_HOOKS];
extern void (*const rgl_glut_text_hooks[RGL_GLUT_TEXT_HOOKS])(void);

/* Appends one @NotRecorded command per entry point counted since the last
 * flush to b (NULL: through the stream's write window, onto its open
 * frame), and zeroes those counts. Calling thread's stream only. Stops at
 * the first record that cannot be written (the recorder has failed then;
 * nothing will be written any more). */
void rgl_unrecorded_flush(rgl_stream *s, rgl_buf *b);

#endif
