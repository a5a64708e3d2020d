/* e2e_torus.c: the end-to-end benchmark's GL program (bench/e2e.sh).
 *
 * Written as an ordinary immediate-mode program would be, with plain gl*
 * calls: an OSMesa context, one lit torus with a colour per vertex, each
 * ring of it a GL_TRIANGLE_STRIP of glColor3f, glNormal3f, glVertex3f,
 * then glFinish. The build makes two programs of it: e2e_torus_plain (GL
 * alone) and e2e_torus_rec (the drop-in header raygl/gl.h on the command
 * line, linked with libraygl; the trace is RAYGL_TRACE and the frame is
 * written at exit), so that what recording costs is the difference of two
 * runs of the same code.
 *
 *   e2e_torus_{plain,rec} [--tris N] [--size WxH] [--no-context] [--ppm FILE]
 *
 * --tris     triangles drawn (default 250000): sides = sqrt(N / 4) around
 *            the tube, rings = N / (2 sides) around the hole, so 10000,
 *            250000 and 1000000 come out exact
 * --size     the OSMesa buffer and viewport (default 640x480)
 * --no-context  no context is made current: GL's calls land in its no-op
 *            dispatch, so only the program's and the recorder's own work
 *            remains
 * --ppm      writes the GL image (binary PPM), to look at
 *
 * Prints one line: the triangles, vertices and GL calls of the frame.
 * Exit 0, 1 on failure, 2 on bad usage.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/osmesa.h>

#include <GL/gl.h>

#define PROG "e2e_torus"
#define MAX_TRIS 100000000L
#define MAX_SIDE 16384

static int usage(const char *why)
{
    fprintf(stderr, PROG ": %s\nusage: " PROG " [--tris N] [--size WxH] [--no-context] [--ppm FILE]\n",
            why);
    return 2;
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno != 0 || end == s || *end != '\0' || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

static int write_ppm(const char *path, const unsigned char *rgba, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, PROG ": %s: %s\n", path, strerror(errno));
        return 1;
    }
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    /* GL's rows run bottom to top; PPM's top to bottom. */
    for (int y = h - 1; y >= 0; y--)
        for (int x = 0; x < w; x++)
            fwrite(rgba + ((size_t)y * (size_t)w + (size_t)x) * 4, 1, 3, f);
    if (fclose(f) != 0) {
        fprintf(stderr, PROG ": %s: %s\n", path, strerror(errno));
        return 1;
    }
    return 0;
}

/* The torus: `rings` strips around the hole, each a strip of 2 (sides + 1)
 * vertices around the tube. Returns the GL calls made. */
static long draw_torus(int rings, int sides, const float *cu, const float *su, const float *cv,
                       const float *sv)
{
    const float big = 1.0f, small = 0.4f;
    long calls = 0;
    for (int i = 0; i < rings; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= sides; j++) {
            for (int k = 1; k >= 0; k--) {
                int r = i + k;
                float nx = cv[j] * cu[r], ny = cv[j] * su[r], nz = sv[j];
                float rad = big + small * cv[j];
                glColor3f(0.5f + 0.5f * cu[r], 0.5f + 0.5f * sv[j], 0.5f - 0.5f * su[r] * cv[j]);
                glNormal3f(nx, ny, nz);
                glVertex3f(rad * cu[r], rad * su[r], small * sv[j]);
            }
        }
        glEnd();
        calls += 2 + 6L * (sides + 1);
    }
    return calls;
}

static long draw(int w, int h, int rings, int sides, const float *cu, const float *su,
                 const float *cv, const float *sv)
{
    static const GLfloat light_dir[4] = {0.5f, 1.0f, 1.5f, 0.0f};
    static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
    const double aspect = (double)w / (double)h, near = 1.0;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5 * aspect * near, 0.5 * aspect * near, -0.5 * near, 0.5 * near, near, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHTING);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    glTranslatef(0.0f, 0.0f, -3.6f);
    glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    long calls = 21 + draw_torus(rings, sides, cu, su, cv, sv);
    glFinish();
    return calls + 1;
}

int main(int argc, char **argv)
{
    long tris = 250000, w = 640, h = 480;
    int context = 1;
    const char *ppm = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--no-context") == 0) {
            context = 0;
        } else if (i + 1 >= argc) {
            return usage(strcmp(a, "--tris") == 0 || strcmp(a, "--size") == 0 ||
                                 strcmp(a, "--ppm") == 0
                             ? "an option lacks its value"
                             : "unknown option");
        } else if (strcmp(a, "--tris") == 0) {
            if (parse_long(argv[++i], 8, MAX_TRIS, &tris) != 0)
                return usage("--tris: a whole number from 8 to 100000000");
        } else if (strcmp(a, "--size") == 0) {
            const char *v = argv[++i], *x = strchr(v, 'x');
            char wpart[16];
            if (!x || (size_t)(x - v) >= sizeof wpart)
                return usage("--size: WxH");
            memcpy(wpart, v, (size_t)(x - v));
            wpart[x - v] = '\0';
            if (parse_long(wpart, 1, MAX_SIDE, &w) != 0 || parse_long(x + 1, 1, MAX_SIDE, &h) != 0)
                return usage("--size: WxH, each 1 to 16384");
        } else if (strcmp(a, "--ppm") == 0) {
            ppm = argv[++i];
        } else {
            return usage("unknown option");
        }
    }
    if (ppm && !context)
        return usage("--ppm needs a context");

    int sides = (int)lround(sqrt((double)tris / 4.0));
    if (sides < 2)
        sides = 2;
    int rings = (int)lround((double)tris / (2.0 * sides));
    if (rings < 2)
        rings = 2;

    int rc = 1;
    unsigned char *pixels = NULL;
    OSMesaContext ctx = NULL;
    float *tab = malloc(sizeof(float) * 2 * ((size_t)rings + 1 + (size_t)sides + 1));
    if (!tab) {
        fprintf(stderr, PROG ": out of memory\n");
        return 1;
    }
    float *cu = tab, *su = cu + rings + 1, *cv = su + rings + 1, *sv = cv + sides + 1;
    const double two_pi = 6.283185307179586;
    for (int i = 0; i <= rings; i++) {
        cu[i] = (float)cos(two_pi * i / rings);
        su[i] = (float)sin(two_pi * i / rings);
    }
    for (int j = 0; j <= sides; j++) {
        cv[j] = (float)cos(two_pi * j / sides);
        sv[j] = (float)sin(two_pi * j / sides);
    }

    if (context) {
        pixels = malloc((size_t)w * (size_t)h * 4);
        ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
        if (!pixels || !ctx) {
            fprintf(stderr, PROG ": no OSMesa context (%s)\n", pixels ? "OSMesaCreateContextExt" : "out of memory");
            goto done;
        }
        if (!OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, (GLsizei)w, (GLsizei)h)) {
            fprintf(stderr, PROG ": OSMesaMakeCurrent failed\n");
            goto done;
        }
    }
    long calls = draw((int)w, (int)h, rings, sides, cu, su, cv, sv);
    printf(PROG ": %ld triangles, %ld vertices, %ld GL calls, %ldx%ld%s\n",
           2L * rings * sides, 2L * rings * (sides + 1), calls, w, h, context ? "" : ", no context");
    rc = ppm ? write_ppm(ppm, pixels, (int)w, (int)h) : 0;
done:
    if (ctx)
        OSMesaDestroyContext(ctx);
    free(pixels);
    free(tab);
    return rc;
}
