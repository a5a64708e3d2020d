/* forward.h: how libraygl's twins reach the real GL.
 *
 * A process may hold two GLs: libGL (GLX, EGL; glvnd's dispatch) and
 * libOSMesa, each exporting the gl* names. A direct call binds to whichever
 * the program linked first, and glvnd's libGL draws nothing while the
 * current context is OSMesa's. So libraygl's sources are built with
 * forward_real.h (generated) force-included: each gl* call goes through the
 * calling thread's table, the functions of the GL whose context is current.
 * The table is chosen on the thread's first call and again at every frame
 * start and end (rgl_forward_select); the call itself is a thread-local
 * load and an indirect call, no lock and no system call.
 */
#ifndef RGL_FORWARD_H
#define RGL_FORWARD_H

#include <stdbool.h>

typedef void (*rgl_fwd_fn)(void);

#if defined(__GNUC__)
extern __thread const rgl_fwd_fn *rgl_tls_fwd __attribute__((tls_model("initial-exec")));
#else
extern _Thread_local const rgl_fwd_fn *rgl_tls_fwd;
#endif

/* Chooses the calling thread's table from the contexts current on it: with
 * an OSMesa context current and no GLX or EGL one, libOSMesa's functions;
 * otherwise the ones the dynamic linker binds the names to. Builds each
 * table once per process (dlsym). Returns the table, never NULL; a function
 * found nowhere is a stub that returns 0. Thread-safe. */
const rgl_fwd_fn *rgl_forward_select(void);

/* Points libglut's GOT slots for the names of rgl_glut_text_names at
 * rgl_glut_text_hooks (unrecorded.h, gluttext.c), once per process; a
 * relink for OSMesa keeps them. Returns whether they are in place (false
 * where relink.c cannot write them). Thread-safe. */
bool rgl_forward_glut_text(void);

#define RGL_FWD_TABLE() (__builtin_expect(rgl_tls_fwd != 0, 1) ? rgl_tls_fwd : rgl_forward_select())
#define RGL_FWD_CALL(i, name, ...) ((__typeof__(name) *)RGL_FWD_TABLE()[i])(__VA_ARGS__)

#endif
