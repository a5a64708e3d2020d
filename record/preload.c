/* preload.c: what libraygl-preload.so adds to the recorder so that an
 * unmodified program is recorded with LD_PRELOAD (docs/design.md, "Recording
 * unmodified programs").
 *
 * - The exported gl*, glu*, glut* names of the recorded calls are the raygl*
 *   twins themselves (preload.ld, generated); the recorder's own calls to
 *   them reach the real functions through rgl_real_fns (preload.h).
 * - Frame ends: glXSwapBuffers, eglSwapBuffers (glutSwapBuffers is a twin),
 *   and glFlush/glFinish while drawing to the front buffer.
 * - Lookups: glXGetProcAddress(ARB), eglGetProcAddress and dlsym on a GL
 *   library's handle return the recording function for the names RayGL
 *   knows, and what they found becomes the real function.
 * - A program that links libraygl itself: this library stands down.
 * (`raygl record`'s status file and --exit are the recorder's: session.c.)
 */
#include <dlfcn.h>
#include <link.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define RGL_PRELOAD_NAMES
#include "preload_real.h"

#include <GL/glx.h>

#include "raygl.h"
#include "recorder.h"

/* Defined here as frame ends, not as aliases of their twins. */
#undef glFlush
#undef glFinish

/* EGL's types as its ABI has them (no EGL headers or library needed). */
typedef unsigned int rgl_egl_boolean;
RGL_EXPORT rgl_egl_boolean eglSwapBuffers(void *dpy, void *surface);
RGL_EXPORT rgl_real_fn eglGetProcAddress(const char *name);

/* ---- The real functions ---------------------------------------------------- */

rgl_real_fn rgl_real_fns[RGL_REAL_COUNT];

/* The twins, in preload_real.h's order (the table's GL, GLU, GLUT rows). */
#define RGL_OURS_GL(name) (rgl_real_fn)RGL_APIFN_GL(name),
#define RGL_OURS_GLU(name) (rgl_real_fn)RGL_APIFN_GLU(name),
#define RGL_OURS_GLUT(name) (rgl_real_fn)RGL_APIFN_GLUT(name),
#define RGL_OURS_RAY(name)
#define RGL_OURS_REC(name)
static const rgl_real_fn ours[] = {
#define RGL_CMD(op, api, gen, name, handler, ...) RGL_OURS_##api(name)
#include "commands.def"
#undef RGL_CMD
};
_Static_assert(sizeof ours / sizeof ours[0] <= RGL_REAL_COUNT, "preload_real.h out of step");

/* The hooks defined in this file, with their real functions. */
enum { H_GLX_SWAP, H_EGL_SWAP, H_GLX_GPA, H_GLX_GPA_ARB, H_EGL_GPA, H_FLUSH, H_FINISH, H_COUNT };
static const char *const hook_names[H_COUNT] = {
    "glXSwapBuffers", "eglSwapBuffers", "glXGetProcAddress", "glXGetProcAddressARB",
    "eglGetProcAddress", "glFlush", "glFinish",
};
static rgl_real_fn hook_real[H_COUNT];
static rgl_real_fn hook_ours(int h);

/* libc's dlsym (ours is the exported one); used by the x86-64 dlsym thunk. */
__attribute__((visibility("hidden"), used)) void *(*rgl_dlsym_next)(void *, const char *);
/* The last GL library handle the program looked a name up in. */
static void *_Atomic gl_handle;

static rgl_real_fn fn_from(void *p)
{
    rgl_real_fn f;
    memcpy(&f, &p, sizeof f);
    return f;
}

static void *ptr_from(rgl_real_fn f)
{
    void *p;
    memcpy(&p, &f, sizeof p);
    return p;
}

/* A sanitizer runtime looks its functions up with dlsym while it starts,
 * before instrumented code may run: the dlsym path is not instrumented. */
#define RGL_NO_SANITIZE __attribute__((no_sanitize("address", "undefined")))

RGL_NO_SANITIZE static void *(*real_dlsym(void))(void *, const char *)
{
    void *(*f)(void *, const char *) = rgl_dlsym_next;
    if (f)
        return f;
    /* dlsym's version differs by libc release and architecture. */
    static const char *const versions[] = {"GLIBC_2.34", "GLIBC_2.2.5", "GLIBC_2.17", "GLIBC_2.0"};
    for (size_t i = 0; i < sizeof versions / sizeof versions[0] && !f; i++) {
        void *p = dlvsym(RTLD_NEXT, "dlsym", versions[i]);
        memcpy(&f, &p, sizeof f);
    }
    rgl_dlsym_next = f;
    return f;
}

/* What a name means after this library: dlsym(RTLD_NEXT), then the GL
 * library the program opened itself, then GL's own lookup. */
static rgl_real_fn find_next(const char *name)
{
    void *(*ds)(void *, const char *) = real_dlsym();
    if (!ds)
        return NULL;
    void *p = ds(RTLD_NEXT, name);
    void *h = atomic_load(&gl_handle);
    if (!p && h)
        p = ds(h, name);
    /* GL's lookup answers any gl* name with a dispatch stub: not for GLU
     * and GLUT, which it does not hold. */
    if (!p && strncmp(name, "gl", 2) == 0 && strncmp(name, "glu", 3) != 0) {
        rgl_real_fn gpa = hook_real[H_GLX_GPA_ARB];
        if (!gpa)
            gpa = fn_from(ds(RTLD_NEXT, "glXGetProcAddressARB"));
        if (gpa)
            p = ptr_from(((rgl_real_fn(*)(const GLubyte *))gpa)((const GLubyte *)name));
    }
    return fn_from(p);
}

/* Stands in for a real function found nowhere: the program could only
 * have reached the caller through a library that has it, so this is never
 * expected to run; it keeps a call from jumping to address 0. */
static long missing(void) { return 0; }

rgl_real_fn rgl_real_resolve(unsigned index)
{
    rgl_real_fn f = find_next(rgl_real_names[index]);
    if (index < sizeof ours / sizeof ours[0] && f == ours[index])
        f = NULL;
    if (!f)
        return (rgl_real_fn)missing;
    rgl_real_fns[index] = f;
    return f;
}

/* The real functions of the entry points passed through unrecorded
 * (preload_unrecorded.h), found at their first call or lookup. A function
 * found in this library itself would call itself: refused. */
rgl_real_fn rgl_unrecorded_fns[RGL_UNRECORDED_COUNT];

static bool in_this_library(rgl_real_fn f)
{
    Dl_info mine, theirs;
    return dladdr(ptr_from((rgl_real_fn)rgl_unrecorded_resolve), &mine) &&
           dladdr(ptr_from(f), &theirs) && mine.dli_fbase == theirs.dli_fbase;
}

rgl_real_fn rgl_unrecorded_resolve(unsigned index)
{
    rgl_real_fn f = find_next(rgl_unrecorded_names[index]);
    if (!f || in_this_library(f))
        return (rgl_real_fn)missing;
    rgl_unrecorded_fns[index] = f;
    return f;
}

/* The index of an unrecorded entry point's name, or -1 (the names are
 * sorted). */
static int unrecorded_index(const char *name)
{
    int lo = 0, hi = RGL_UNRECORDED_COUNT - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        int c = strcmp(name, rgl_unrecorded_names[mid]);
        if (c == 0)
            return mid;
        if (c < 0)
            hi = mid - 1;
        else
            lo = mid + 1;
    }
    return -1;
}

static rgl_real_fn real_hook(int h)
{
    rgl_real_fn f = hook_real[h];
    if (!f) {
        f = find_next(hook_names[h]);
        if (f == hook_ours(h))
            f = NULL;
        hook_real[h] = f;
    }
    return f;
}

/* ---- The passthrough guard ------------------------------------------------- */

int rgl_guard_enter(void)
{
    rgl_stream *s = rgl_tls_stream;
    if (s)
        s->end = s->pos; /* the next call takes the slow path, which sees the guard */
    return ++rgl_tls_passthrough;
}

void rgl_guard_leave(int *depth)
{
    (void)depth;
    rgl_tls_passthrough--;
}

/* ---- Frame ends ------------------------------------------------------------ */

/* Before a swap: the swap itself, then the shown image (read before the
 * back buffer becomes undefined). */
static void swap_begin(void)
{
    rgl_record(RGL_OP_SwapBuffers, "");
    rgl_frame_image();
}

RGL_EXPORT void glXSwapBuffers(Display *dpy, GLXDrawable drawable)
{
    void (*real)(Display *, GLXDrawable) = (void (*)(Display *, GLXDrawable))real_hook(H_GLX_SWAP);
    if (!real)
        return;
    if (rgl_tls_passthrough > 0) {
        real(dpy, drawable);
        return;
    }
    swap_begin();
    rgl_guard_enter(); /* GL's own calls inside the swap, if any */
    real(dpy, drawable);
    rgl_guard_leave(NULL);
    rgl_frame_end();
}

RGL_EXPORT rgl_egl_boolean eglSwapBuffers(void *dpy, void *surface)
{
    rgl_egl_boolean (*real)(void *, void *) =
        (rgl_egl_boolean(*)(void *, void *))real_hook(H_EGL_SWAP);
    if (!real)
        return 0;
    if (rgl_tls_passthrough > 0)
        return real(dpy, surface);
    swap_begin();
    rgl_guard_enter();
    rgl_egl_boolean ok = real(dpy, surface);
    rgl_guard_leave(NULL);
    rgl_frame_end();
    return ok;
}

/* A single-buffered program shows its frame by flushing drawing to the
 * front buffer. */
static void flush_end(void)
{
    rgl_stream *s = rgl_tls_stream;
    if (rgl_tls_passthrough > 0 || !s || s->in_begin || s->compiling)
        return;
    GLint buf = 0;
    glGetIntegerv(GL_DRAW_BUFFER, &buf);
    if (buf == GL_FRONT || buf == GL_FRONT_LEFT || buf == GL_FRONT_RIGHT ||
        buf == GL_FRONT_AND_BACK || buf == GL_LEFT || buf == GL_RIGHT)
        rgl_frame_end();
}

RGL_EXPORT void glFlush(void)
{
    rayglFlush();
    flush_end();
}

RGL_EXPORT void glFinish(void)
{
    rayglFinish();
    flush_end();
}

/* ---- Lookups --------------------------------------------------------------- */

static rgl_real_fn hook_ours(int h)
{
    switch (h) {
    case H_GLX_SWAP: return (rgl_real_fn)glXSwapBuffers;
    case H_EGL_SWAP: return (rgl_real_fn)eglSwapBuffers;
    case H_GLX_GPA: return (rgl_real_fn)glXGetProcAddress;
    case H_GLX_GPA_ARB: return (rgl_real_fn)glXGetProcAddressARB;
    case H_EGL_GPA: return (rgl_real_fn)eglGetProcAddress;
    case H_FLUSH: return (rgl_real_fn)glFlush;
    case H_FINISH: return (rgl_real_fn)glFinish;
    }
    return NULL;
}

/* What a lookup of `name` that found `real` returns to the program: the
 * recording function for a name RayGL records, and `real` becomes the
 * function it forwards to (when none was found before). */
static rgl_real_fn intercept(const char *name, rgl_real_fn real)
{
    if (!real || !name)
        return real;
    for (int h = 0; h < H_COUNT; h++) {
        if (strcmp(name, hook_names[h]) == 0) {
            rgl_real_fn mine = hook_ours(h);
            if (real != mine && !hook_real[h])
                hook_real[h] = real;
            return mine;
        }
    }
    if (strncmp(name, "gl", 2) != 0)
        return real;
    for (size_t i = 0; i < sizeof ours / sizeof ours[0]; i++) {
        if (strcmp(name, rgl_real_names[i]) == 0) {
            if (real != ours[i] && !rgl_real_fns[i])
                rgl_real_fns[i] = real;
            return ours[i];
        }
    }
    int u = unrecorded_index(name);
    if (u >= 0) {
        if (!rgl_unrecorded_fns[u] && !in_this_library(real))
            rgl_unrecorded_fns[u] = real;
        return rgl_unrecorded_twins[u] ? rgl_unrecorded_twins[u] : real; /* NULL: seen through */
    }
    return real;
}

RGL_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte *name)
{
    rgl_real_fn real = real_hook(H_GLX_GPA_ARB);
    rgl_real_fn f = real ? ((rgl_real_fn(*)(const GLubyte *))real)(name) : NULL;
    return (__GLXextFuncPtr)intercept((const char *)name, f);
}

RGL_EXPORT __GLXextFuncPtr glXGetProcAddress(const GLubyte *name)
{
    rgl_real_fn real = real_hook(H_GLX_GPA);
    rgl_real_fn f = real ? ((rgl_real_fn(*)(const GLubyte *))real)(name) : NULL;
    return (__GLXextFuncPtr)intercept((const char *)name, f);
}

RGL_EXPORT rgl_real_fn eglGetProcAddress(const char *name)
{
    rgl_real_fn real = real_hook(H_EGL_GPA);
    rgl_real_fn f = real ? ((rgl_real_fn(*)(const char *))real)(name) : NULL;
    return intercept(name, f);
}

/* Whether a dlopen handle is one of the GL libraries (glvnd's or not), by
 * its file name. The vendor libraries glvnd loads (libGLX_mesa, libEGL_mesa)
 * do not match: their lookups are glvnd's own business. */
static bool is_gl_library(void *handle)
{
    struct link_map *lm = NULL;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &lm) != 0 || !lm || !lm->l_name)
        return false;
    const char *base = strrchr(lm->l_name, '/');
    base = base ? base + 1 : lm->l_name;
    static const char *const libs[] = {"libGL.so", "libOpenGL.so", "libGLX.so", "libEGL.so",
                                       "libGLU.so", "libglut.so", "libGLESv1_CM.so"};
    for (size_t i = 0; i < sizeof libs / sizeof libs[0]; i++)
        if (strncmp(base, libs[i], strlen(libs[i])) == 0)
            return true;
    return false;
}

/* dlsym on a GL library's handle. RTLD_NEXT is answered for the caller by
 * the x86-64 thunk below (a tail jump keeps the caller's return address,
 * which is how libc knows who asked); elsewhere it is answered as if asked
 * by this library, which differs only for names this library defines. */
RGL_NO_SANITIZE __attribute__((visibility("hidden"), used)) void *rgl_dlsym_hook(void *handle,
                                                                                  const char *name)
{
    void *(*ds)(void *, const char *) = real_dlsym();
    if (!ds)
        return NULL;
    void *p = ds(handle, name);
    if (!p || !name || handle == RTLD_DEFAULT || handle == RTLD_NEXT || !is_gl_library(handle))
        return p;
    atomic_store(&gl_handle, handle);
    return ptr_from(intercept(name, fn_from(p)));
}

#if defined(__x86_64__)
__asm__(".text\n"
        ".globl dlsym\n"
        ".type dlsym, @function\n"
        "dlsym:\n"
        "    endbr64\n"
        "    cmpq $-1, %rdi\n" /* RTLD_NEXT */
        "    jne 1f\n"
        "    movq rgl_dlsym_next(%rip), %rax\n"
        "    testq %rax, %rax\n"
        "    jz 1f\n"
        "    jmp *%rax\n"
        "1:  jmp rgl_dlsym_hook\n"
        ".size dlsym, .-dlsym\n");
#else
RGL_EXPORT void *dlsym(void *handle, const char *name) { return rgl_dlsym_hook(handle, name); }
#endif

/* ---- Start ----------------------------------------------------------------- */

/* The real functions are found once here; those of a GL library the
 * program opens later, at their first use or lookup.
 *
 * A program that links libraygl (built with the drop-in header) records
 * with it: this library then stands down, and only forwards, or both
 * would record the program (two traces, the one raygl record names cut
 * short when the other's RAYGL_EXIT ends the program). libraygl reads the
 * same variables (RAYGL_TRACE, the frame selection, RAYGL_EXIT,
 * RAYGL_STATUS_FILE). This library exports no raygl* name, so the lookup
 * finds libraygl's only. */
__attribute__((constructor)) static void preload_init(void)
{
    void *(*ds)(void *, const char *) = real_dlsym();
    for (unsigned i = 0; ds && i < RGL_REAL_COUNT; i++) {
        rgl_real_fn f = fn_from(ds(RTLD_NEXT, rgl_real_names[i]));
        if (f && (i >= sizeof ours / sizeof ours[0] || f != ours[i]))
            rgl_real_fns[i] = f;
    }
    if (ds && ds(RTLD_DEFAULT, "rayglRecordOpen"))
        rgl_recorder_stand_down();
    else
        rgl_recorder_init();
}
