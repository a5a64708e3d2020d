/* forward.c: the tables of real GL functions libraygl forwards to
 * (forward.h), and the choice of one per thread.
 *
 * Two tables: "linked", each name as the dynamic linker binds it (what a
 * direct call would reach), and "osmesa", each name from libOSMesa itself.
 * They differ only when libGL comes before libOSMesa in the program's link
 * order; the osmesa table is then the one that draws into an OSMesa context.
 */
#define RGL_FORWARD_NAMES
#include "forward_real.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <string.h>

#include <GL/glu.h>
#include <GL/freeglut.h>
#include <GL/glx.h>

#include "recorder.h"
#include "relink.h"
#include "unrecorded.h"

#if defined(__GNUC__)
__thread const rgl_fwd_fn *rgl_tls_fwd __attribute__((tls_model("initial-exec")));
#else
_Thread_local const rgl_fwd_fn *rgl_tls_fwd;
#endif

static rgl_fwd_fn linked[RGL_FWD_COUNT], osmesa[RGL_FWD_COUNT];
static pthread_once_t linked_once = PTHREAD_ONCE_INIT, osmesa_once = PTHREAD_ONCE_INIT;

/* What a call to a function found nowhere does: GL's answer without a
 * context (nothing drawn, 0 returned). */
static long fwd_none(void) { return 0; }

static rgl_fwd_fn fn_from(void *p)
{
    rgl_fwd_fn f;
    memcpy(&f, &p, sizeof f);
    return f;
}

static void build_linked(void)
{
    for (size_t i = 0; i < RGL_FWD_COUNT; i++) {
        rgl_fwd_fn f = fn_from(dlsym(RTLD_DEFAULT, rgl_fwd_names[i]));
        if (!f)
            f = glXGetProcAddressARB((const GLubyte *)rgl_fwd_names[i]);
        linked[i] = f ? f : (rgl_fwd_fn)fwd_none;
    }
}

/* OSMesa's entry points, looked up once; NULL until libOSMesa is loaded. */
static void *(*_Atomic osmesa_current)(void);
static rgl_fwd_fn (*osmesa_gpa)(const char *);

/* Whether the tables differ (libGL linked before libOSMesa), and which one
 * the gl* imports of GLU, GLUT and the program point at (relink.c). */
static _Atomic bool mismatch;
static const rgl_fwd_fn *relinked;
static pthread_mutex_t relink_mu = PTHREAD_MUTEX_INITIALIZER;

static void build_osmesa(void)
{
    pthread_once(&linked_once, build_linked);
    void *(*cur)(void) = osmesa_current;
    void *h = NULL;
    Dl_info info;
    void *p;
    memcpy(&p, &cur, sizeof p);
    /* The library that defines OSMesaGetCurrentContext, whatever its soname. */
    if (dladdr(p, &info) && info.dli_fname)
        h = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
    for (size_t i = 0; i < RGL_FWD_COUNT; i++) {
        rgl_fwd_fn f = h ? fn_from(dlsym(h, rgl_fwd_names[i])) : NULL;
        if (!f && osmesa_gpa)
            f = osmesa_gpa(rgl_fwd_names[i]);
        osmesa[i] = f ? f : linked[i];
        if (osmesa[i] != linked[i])
            mismatch = true;
    }
    /* h stays open: the table points into the library. */
}

/* Whether an OSMesa context is current on this thread; looks OSMesa up
 * until it is loaded (a program may dlopen it late). */
static bool osmesa_is_current(void)
{
    void *(*cur)(void) = osmesa_current;
    if (!cur) {
        void *p = dlsym(RTLD_DEFAULT, "OSMesaGetCurrentContext");
        if (!p)
            return false;
        void *g = dlsym(RTLD_DEFAULT, "OSMesaGetProcAddress");
        memcpy(&osmesa_gpa, &g, sizeof g);
        memcpy(&cur, &p, sizeof cur);
        osmesa_current = cur;
    }
    return cur() != NULL;
}

static bool egl_is_current(void)
{
    static void *(*_Atomic cur)(void);
    void *(*f)(void) = cur;
    if (!f) {
        void *p = dlsym(RTLD_DEFAULT, "eglGetCurrentContext");
        if (!p)
            return false;
        memcpy(&f, &p, sizeof f);
        cur = f;
    }
    return f() != NULL;
}

/* GLUT's text hooks (gluttext.c): 0 not tried yet, 1 in place, -1 not
 * possible. Written under relink_mu. */
static _Atomic int text_hooked;

/* Under relink_mu. */
static int hook_glut_text(void)
{
    void (*glut)(void) = (rgl_fwd_fn)glutBitmapCharacter;
    void *p;
    memcpy(&p, &glut, sizeof p);
    return rgl_relink(p, rgl_glut_text_names, rgl_glut_text_hooks, RGL_GLUT_TEXT_HOOKS);
}

bool rgl_forward_glut_text(void)
{
    int h = text_hooked;
    if (h == 0) {
        pthread_mutex_lock(&relink_mu);
        if (text_hooked == 0)
            text_hooked = hook_glut_text() == 0 ? 1 : -1;
        h = text_hooked;
        pthread_mutex_unlock(&relink_mu);
    }
    return h > 0;
}

/* The gl* calls of GLU, GLUT and the program go where the twins' go
 * (relink.c). */
static void relink_shapes(const rgl_fwd_fn *t)
{
    pthread_mutex_lock(&relink_mu);
    if (relinked != t && !(relinked == NULL && t == linked)) {
        void (*glu)(void), (*glut)(void);
        void *p;
        glu = (rgl_fwd_fn)gluSphere;
        glut = (rgl_fwd_fn)glutSolidSphere;
        memcpy(&p, &glu, sizeof p);
        rgl_relink(p, rgl_fwd_names, t, RGL_FWD_COUNT);
        memcpy(&p, &glut, sizeof p);
        rgl_relink(p, rgl_fwd_names, t, RGL_FWD_COUNT);
        rgl_relink(NULL, rgl_fwd_names, t, RGL_FWD_COUNT);
        /* The hooks forward through the thread's table themselves. */
        if (text_hooked > 0)
            hook_glut_text();
        relinked = t;
    }
    pthread_mutex_unlock(&relink_mu);
}

const rgl_fwd_fn *rgl_forward_select(void)
{
    const rgl_fwd_fn *t = linked;
    if (!glXGetCurrentContext() && !egl_is_current() && osmesa_is_current()) {
        pthread_once(&osmesa_once, build_osmesa);
        t = osmesa;
    } else {
        pthread_once(&linked_once, build_linked);
    }
    rgl_tls_fwd = t;
    if (mismatch)
        relink_shapes(t);
    return t;
}
