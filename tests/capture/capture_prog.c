/* capture_prog.c: an ordinary OpenGL program (it knows nothing of RayGL)
 * for the `raygl record` tests. Each frame clears and draws one triangle
 * of 3 vertices (glBegin, glColor3f, glVertex2f, glEnd), then shows it.
 *
 *   --api glx|egl|glut  how the window, context and frame end are made:
 *                       glXSwapBuffers, eglSwapBuffers, glutSwapBuffers
 *   --single            single-buffered GLX: the frame ends at glFlush
 *   --lookup direct|dlsym|next|glx|egl
 *                       where the drawing functions come from: linked,
 *                       dlsym on dlopen("libGL.so.1"), dlsym(RTLD_NEXT)
 *                       (the first definition after the program: what the
 *                       program itself would call), glXGetProcAddressARB,
 *                       eglGetProcAddress
 *   --frames N          frames to draw (default 3)
 *   --threads 2         two threads, each with its own window and context
 *   --teapot            GLUT: each frame is one glutSolidTeapot instead
 *   --nurbs             each frame is one GLU NURBS surface instead (GLU
 *                       draws it through evaluators: glMap2f, glEvalMesh2)
 *   --nurbs-tess        as --nurbs, in GLU_NURBS_TESSELLATOR mode: GLU hands
 *                       the triangles to callbacks that draw them with
 *                       glBegin, glNormal3fv, glVertex3fv, glEnd
 *   --hang FILE         after the frames, start one more (glBegin, two
 *                       vertices), create FILE, and wait to be killed
 *   --exec-child        after frame 0, fork; the child runs this program
 *                       again (--api glx --frames 2)
 *   --fork-child        after frame 0, fork; the child makes GL calls
 *                       (glBegin, glVertex2f(5, 5), glEnd) and exits
 *   --delay-ms N        sleep N ms after each frame
 *   --until FILE        once FILE exists (checked after each frame), one
 *                       more frame, then end as after the last (--frames
 *                       stays the most; one thread)
 *   --done FILE         create FILE once every frame is drawn (a program
 *                       ended early leaves none)
 *   --ignore-term       ignore SIGTERM (raygl record --exit then kills)
 *   --unrecorded        each frame also makes calls RayGL passes through
 *                       unrecorded (glIndexi, glIndexMask,
 *                       glSampleCoverage found with
 *                       glXGetProcAddressARB) and queries (glGetError,
 *                       glGetIntegerv, glIsEnabled); with --api glut
 *                       also bitmap text after the triangle
 *                       (glutBitmapCharacter, glutBitmapString: their
 *                       glBitmap calls are recorded)
 *   --stroke            with --api glut, stroke text after the triangle
 *                       (glutStrokeCharacter, glutStrokeString: their line
 *                       strips are recorded)
 *
 * Built twice: as it is, for raygl record, and with -include raygl/gl.h
 * (capture_prog_dropin), the drop-in header's build of the same program.
 */
#include <EGL/egl.h>
#include <GL/freeglut.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct gl_fns {
    void (*Clear)(GLbitfield);
    void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
    void (*Begin)(GLenum);
    void (*End)(void);
    void (*Color3f)(GLfloat, GLfloat, GLfloat);
    void (*Vertex2f)(GLfloat, GLfloat);
    void (*Flush)(void);
} gl_fns;

static struct {
    const char *api, *lookup, *hang;
    int single, frames, threads, teapot, exec_child, fork_child, delay_ms, unrecorded, nurbs,
        stroke;
    const char *self, *done, *until;
} opt = {"glx", "direct", NULL, 0, 3, 1, 0, 0, 0, 0, 0, 0, 0, NULL, NULL, NULL};

static gl_fns gl;

static void die(const char *what)
{
    fprintf(stderr, "capture_prog: %s\n", what);
    exit(1);
}

static void *fn_ptr(void *p, const char *name)
{
    if (!p) {
        fprintf(stderr, "capture_prog: no %s\n", name);
        exit(1);
    }
    return p;
}

/* The drawing functions, from where --lookup says (after a context exists:
 * eglGetProcAddress may need one). */
static void load_fns(void)
{
    static const char *const names[] = {"glClear",    "glClearColor", "glBegin", "glEnd",
                                        "glColor3f",  "glVertex2f",   "glFlush"};
    void *ptrs[7];
    if (strcmp(opt.lookup, "direct") == 0) {
        gl = (gl_fns){glClear, glClearColor, glBegin, glEnd, glColor3f, glVertex2f, glFlush};
        return;
    }
    void *h = NULL;
    if (strcmp(opt.lookup, "dlsym") == 0 && !(h = dlopen("libGL.so.1", RTLD_NOW | RTLD_LOCAL)))
        die("dlopen libGL.so.1");
    for (int i = 0; i < 7; i++) {
        void (*f)(void) = NULL;
        if (h)
            ptrs[i] = dlsym(h, names[i]);
        else if (strcmp(opt.lookup, "next") == 0)
            ptrs[i] = dlsym(RTLD_NEXT, names[i]);
        else if (strcmp(opt.lookup, "glx") == 0)
            f = glXGetProcAddressARB((const GLubyte *)names[i]);
        else if (strcmp(opt.lookup, "egl") == 0)
            f = eglGetProcAddress(names[i]);
        else
            die("bad --lookup");
        if (!h && strcmp(opt.lookup, "next") != 0)
            memcpy(&ptrs[i], &f, sizeof f);
        fn_ptr(ptrs[i], names[i]);
    }
    memcpy(&gl.Clear, &ptrs[0], sizeof ptrs[0]);
    memcpy(&gl.ClearColor, &ptrs[1], sizeof ptrs[1]);
    memcpy(&gl.Begin, &ptrs[2], sizeof ptrs[2]);
    memcpy(&gl.End, &ptrs[3], sizeof ptrs[3]);
    memcpy(&gl.Color3f, &ptrs[4], sizeof ptrs[4]);
    memcpy(&gl.Vertex2f, &ptrs[5], sizeof ptrs[5]);
    memcpy(&gl.Flush, &ptrs[6], sizeof ptrs[6]);
}

/* Calls RayGL does not record, and queries. */
static void unrecorded_calls(void)
{
    glIndexi(0);
    glIndexMask(~0u);
    void (*sample_coverage)(GLfloat, GLboolean) =
        (void (*)(GLfloat, GLboolean))glXGetProcAddressARB((const GLubyte *)"glSampleCoverage");
    if (sample_coverage)
        sample_coverage(1, GL_FALSE);
    GLint v[4];
    glGetIntegerv(GL_VIEWPORT, v);
    (void)glIsEnabled(GL_LIGHTING);
    while (glGetError() != GL_NO_ERROR)
        ;
}

/* Bitmap text over the frame, as a GLUT program writes it. */
static void bitmap_text(void)
{
    if (strcmp(opt.api, "glut") != 0) /* freeglut exits without glutInit */
        return;
    glColor3f(1, 1, 0);
    glRasterPos2f(-0.9f, -0.9f);
    glutBitmapCharacter(GLUT_BITMAP_8_BY_13, 'R');
    glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char *)"GB");
}

/* Stroke text: freeglut draws each character as line strips, then moves
 * on with glTranslatef. */
static void stroke_text(void)
{
    if (strcmp(opt.api, "glut") != 0)
        return;
    glColor3f(1, 1, 1);
    glPushMatrix();
    glTranslatef(-0.9f, 0.5f, 0);
    glScalef(0.002f, 0.002f, 1);
    glutStrokeCharacter(GLUT_STROKE_ROMAN, 'R');
    glutStrokeString(GLUT_STROKE_MONO_ROMAN, (const unsigned char *)"G\nB");
    glPopMatrix();
}

static void GLAPIENTRY tess_begin(GLenum mode) { glBegin(mode); }
static void GLAPIENTRY tess_vertex(GLfloat *v) { glVertex3fv(v); }
static void GLAPIENTRY tess_normal(GLfloat *n) { glNormal3fv(n); }
static void GLAPIENTRY tess_end(void) { glEnd(); }

static void draw(int frame, int thread)
{
    if (opt.unrecorded)
        unrecorded_calls();
    gl.ClearColor(0.1f * (float)thread, 0.2f, 0.3f, 1);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    if (opt.teapot) {
        glColor3f(1, 0.5f, 0);
        glutSolidTeapot(0.5);
        return;
    }
    if (opt.nurbs) {
        /* The tessellator's callbacks: the program's own drawing. */
        static const struct {
            GLenum which;
            void (*fn)(void);
        } cbs[] = {
            {GLU_NURBS_BEGIN, (void (*)(void))tess_begin},
            {GLU_NURBS_VERTEX, (void (*)(void))tess_vertex},
            {GLU_NURBS_NORMAL, (void (*)(void))tess_normal},
            {GLU_NURBS_END, (void (*)(void))tess_end},
        };
        /* A bicubic Bezier patch as a NURBS surface, a dome over [-0.6, 0.6]^2. */
        static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        GLfloat ctl[4][4][3];
        for (int u = 0; u < 4; u++)
            for (int v = 0; v < 4; v++) {
                ctl[u][v][0] = 0.4f * ((float)u - 1.5f);
                ctl[u][v][1] = 0.4f * ((float)v - 1.5f);
                ctl[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 0.6f : 0.0f;
            }
        GLUnurbsObj *n = gluNewNurbsRenderer();
        gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, 25.0f);
        if (opt.nurbs == 2) {
            gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
            for (size_t i = 0; i < sizeof cbs / sizeof cbs[0]; i++)
                gluNurbsCallback(n, cbs[i].which, cbs[i].fn);
        }
        glColor3f(1, 0.5f, 0);
        gluBeginSurface(n);
        gluNurbsSurface(n, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
        gluEndSurface(n);
        gluDeleteNurbsRenderer(n);
        return;
    }
    gl.Begin(GL_TRIANGLES);
    gl.Color3f(1, 0, (float)thread);
    gl.Vertex2f(-0.8f + 0.1f * (float)frame, -0.8f);
    gl.Color3f(0, 1, 0);
    gl.Vertex2f(0.8f, -0.8f);
    gl.Color3f(0, 0, 1);
    gl.Vertex2f(0, 0.8f);
    gl.End();
    if (opt.unrecorded)
        bitmap_text();
    if (opt.stroke)
        stroke_text();
}

/* The extra frame left unfinished for --hang. */
static void hang(void)
{
    gl.Begin(GL_TRIANGLES);
    gl.Vertex2f(0, 0);
    gl.Vertex2f(1, 0);
    int fd = open(opt.hang, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0)
        close(fd);
    for (;;)
        pause();
}

/* Whether frame f is to be drawn. */
static int more(int f)
{
    static int told;
    if (f >= opt.frames || told)
        return 0;
    told = opt.until && access(opt.until, F_OK) == 0;
    return 1;
}

static void after_frame(int frame)
{
    if (opt.delay_ms > 0)
        usleep((useconds_t)opt.delay_ms * 1000u);
    if (frame != 0)
        return;
    if (opt.exec_child || opt.fork_child) {
        pid_t pid = fork();
        if (pid < 0)
            die("fork");
        if (pid == 0) {
            if (opt.exec_child) {
                execl(opt.self, opt.self, "--api", "glx", "--frames", "2", (char *)NULL);
                _exit(127);
            }
            /* Client-side calls only (nothing reaches the X connection
             * shared with the parent); the parent's trace must not see
             * them. */
            glBegin(GL_TRIANGLES);
            glVertex2f(5, 5);
            glEnd();
            _exit(0);
        }
        int st;
        if (waitpid(pid, &st, 0) != pid || !WIFEXITED(st) || WEXITSTATUS(st) != 0)
            die("the child failed");
    }
}

/* ---- GLX --------------------------------------------------------------- */

static void *glx_thread(void *arg)
{
    int thread = (int)(long)arg;
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy)
        die("XOpenDisplay");
    int attrs[] = {GLX_RGBA, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                   opt.single ? None : GLX_DOUBLEBUFFER, None};
    XVisualInfo *vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
    if (!vi)
        die("glXChooseVisual");
    XSetWindowAttributes swa = {0};
    Window root = RootWindow(dpy, vi->screen);
    swa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    Window win = XCreateWindow(dpy, root, 0, 0, 160, 120, 0, vi->depth, InputOutput, vi->visual,
                               CWColormap, &swa);
    XMapWindow(dpy, win);
    GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
    if (!ctx || !glXMakeCurrent(dpy, win, ctx))
        die("glXCreateContext");
    if (thread == 0)
        load_fns();
    for (int f = 0; more(f); f++) {
        draw(f, thread);
        if (opt.single)
            gl.Flush();
        else
            glXSwapBuffers(dpy, win);
        after_frame(f);
    }
    if (opt.hang)
        hang();
    /* Teardown one thread at a time: two XCloseDisplay at once crashed in
     * libXext's XextRemoveDisplay (once, ASan build, XInitThreads called);
     * what is tested is the drawing, not Xlib's teardown. */
    static pthread_mutex_t teardown = PTHREAD_MUTEX_INITIALIZER;
    pthread_mutex_lock(&teardown);
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, ctx);
    XDestroyWindow(dpy, win);
    XFree(vi);
    XCloseDisplay(dpy);
    pthread_mutex_unlock(&teardown);
    return NULL;
}

static void run_glx(void)
{
    if (opt.threads == 1) {
        glx_thread(0);
        return;
    }
    XInitThreads();
    /* The functions are loaded once, before the threads draw. */
    opt.lookup = "direct";
    load_fns();
    pthread_t t[2];
    for (long i = 0; i < 2; i++)
        if (pthread_create(&t[i], NULL, glx_thread, (void *)(i + 1)))
            die("pthread_create");
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
}

/* ---- EGL on an X window ----------------------------------------------------- */

static void run_egl(void)
{
    Display *x = XOpenDisplay(NULL);
    if (!x)
        die("XOpenDisplay");
    EGLDisplay dpy = eglGetDisplay((EGLNativeDisplayType)x);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API))
        die("eglInitialize");
    EGLint attrs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(dpy, attrs, &cfg, 1, &n) || n < 1)
        die("eglChooseConfig");
    EGLint vid;
    eglGetConfigAttrib(dpy, cfg, EGL_NATIVE_VISUAL_ID, &vid);
    XVisualInfo tmpl = {.visualid = (VisualID)vid};
    int nv;
    XVisualInfo *vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &nv);
    if (!vi)
        die("XGetVisualInfo");
    Window root = DefaultRootWindow(x);
    XSetWindowAttributes swa = {0};
    swa.colormap = XCreateColormap(x, root, vi->visual, AllocNone);
    Window win = XCreateWindow(x, root, 0, 0, 160, 120, 0, vi->depth, InputOutput, vi->visual,
                               CWColormap, &swa);
    XMapWindow(x, win);
    EGLSurface surf = eglCreateWindowSurface(dpy, cfg, (EGLNativeWindowType)win, NULL);
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, NULL);
    if (surf == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surf, surf, ctx))
        die("eglCreateContext");
    load_fns();
    for (int f = 0; more(f); f++) {
        draw(f, 0);
        eglSwapBuffers(dpy, surf);
    }
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglDestroySurface(dpy, surf);
    eglTerminate(dpy);
    XFree(vi);
    XDestroyWindow(x, win);
    XCloseDisplay(x);
}

/* ---- GLUT ------------------------------------------------------------------- */

static int glut_frame;

static void glut_display(void)
{
    if (!more(glut_frame)) {
        glutLeaveMainLoop();
        return;
    }
    draw(glut_frame, 0);
    glutSwapBuffers();
    after_frame(glut_frame);
    glut_frame++;
    glutPostRedisplay();
}

static void run_glut(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(160, 120);
    glutCreateWindow("capture_prog");
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    load_fns();
    if (opt.teapot) {
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
    }
    glutDisplayFunc(glut_display);
    glutMainLoop();
}

int main(int argc, char **argv)
{
    opt.self = argv[0];
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--api") == 0 && v)
            opt.api = argv[++i];
        else if (strcmp(a, "--lookup") == 0 && v)
            opt.lookup = argv[++i];
        else if (strcmp(a, "--frames") == 0 && v)
            opt.frames = atoi(argv[++i]);
        else if (strcmp(a, "--threads") == 0 && v)
            opt.threads = atoi(argv[++i]);
        else if (strcmp(a, "--hang") == 0 && v)
            opt.hang = argv[++i];
        else if (strcmp(a, "--delay-ms") == 0 && v)
            opt.delay_ms = atoi(argv[++i]);
        else if (strcmp(a, "--single") == 0)
            opt.single = 1;
        else if (strcmp(a, "--unrecorded") == 0)
            opt.unrecorded = 1;
        else if (strcmp(a, "--stroke") == 0)
            opt.stroke = 1;
        else if (strcmp(a, "--teapot") == 0)
            opt.teapot = 1;
        else if (strcmp(a, "--nurbs") == 0)
            opt.nurbs = 1;
        else if (strcmp(a, "--nurbs-tess") == 0)
            opt.nurbs = 2;
        else if (strcmp(a, "--exec-child") == 0)
            opt.exec_child = 1;
        else if (strcmp(a, "--fork-child") == 0)
            opt.fork_child = 1;
        else if (strcmp(a, "--until") == 0 && v)
            opt.until = argv[++i];
        else if (strcmp(a, "--done") == 0 && v)
            opt.done = argv[++i];
        else if (strcmp(a, "--ignore-term") == 0)
            signal(SIGTERM, SIG_IGN);
        else {
            fprintf(stderr, "capture_prog: bad argument %s\n", a);
            return 2;
        }
    }
    if (opt.frames < 1 || opt.frames > 1000 || opt.delay_ms < 0 || opt.delay_ms > 1000 || (opt.threads != 1 && opt.threads != 2))
        die("bad --frames or --threads");
    if (strcmp(opt.api, "glx") == 0)
        run_glx();
    else if (strcmp(opt.api, "egl") == 0)
        run_egl();
    else if (strcmp(opt.api, "glut") == 0)
        run_glut(argc, argv);
    else
        die("bad --api");
    if (opt.done) {
        int fd = open(opt.done, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0)
            die("cannot create the --done file");
        close(fd);
    }
    return 0;
}
