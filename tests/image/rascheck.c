/* rascheck.c: translate/gl/rasterise.c against Mesa's own rasterisation.
 *
 *     rascheck [N]
 *
 * Draws N random aliased lines (widths 1 to 5; ends on whole pixels, the
 * 1/4, 1/16 and 1/4096 grids, so that many fall on pixel edges, centres and
 * corners; some cross the frame's edges) and N random points (square and
 * round, whole and fractional sizes) one at a time into an OSMesa frame,
 * reads the pixels back and compares them with what rasterise.c says GL
 * lights. Exit 0 when every pixel agrees; 1 after printing the first
 * disagreements. Round points whose circle passes exactly through a pixel
 * centre are left out: Mesa's float rounding decides those (rasterise.h).
 * The frame is 256 x 128 under glOrtho(0, 256, 0, 128): window
 * coordinates are then exact in float, as the translator's are in double.
 * Then N/2 short lines with decimal ends (0.1 steps: GL's float puts many
 * within a rounding of a pixel edge or a diamond's corner) in a 320 x 240
 * frame under gluOrtho2D, once with an identity modelview and once scaled
 * and turned, their window positions taken from ras_window (Mesa's float
 * transform) with the matrices GL reports.
 */
#include <GL/osmesa.h>

#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rasterise.h"

#define W 256
#define H 128

static unsigned char rgba[W * H * 4];

/* A small deterministic generator (the figures must not depend on libc). */
static uint32_t rng = 12345;
static uint32_t next(void)
{
    rng = rng * 1664525u + 1013904223u;
    return rng >> 8;
}
static double grid(double lo, double span, int q) { return lo + (double)(next() % (uint32_t)(span * q)) / q; }

static void read_lit(unsigned char *lit)
{
    glFinish();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    for (int k = 0; k < W * H; k++)
        lit[k] = rgba[4 * k] > 128;
}

static int report(const char *what, const unsigned char *gl, const unsigned char *model, int shown)
{
    int d = 0;
    for (int k = 0; k < W * H; k++)
        if (gl[k] != model[k]) {
            if (shown < 10 && d < 6)
                printf("  %s: pixel (%d, %d) %s\n", what, k % W, k / W, gl[k] ? "lit by GL only" : "lit by the model only");
            d++;
        }
    return d;
}

static int check_lines(int n, ras_run *runs)
{
    static unsigned char gl[W * H], model[W * H];
    static const int q[4] = {1, 4, 16, 4096};
    int bad = 0;
    for (int i = 0; i < n; i++) {
        int g = q[i % 4];
        double p[2][2];
        p[0][0] = grid(-10, W + 20, g);
        p[0][1] = grid(-10, H + 20, g);
        double len = next() % 3 == 0 ? grid(0, 4, g) : grid(0, 80, g), a;
        a = next() % 4 == 0 ? (next() % 8) * 3.14159265358979 / 4 : (next() % 3600) * 3.14159265358979 / 1800;
        p[1][0] = p[0][0] + floor(len * cos(a) * g) / g;
        p[1][1] = p[0][1] + floor(len * sin(a) * g) / g;
        float w = next() % 3 == 0 ? (float)(1 + next() % 5) : 1;
        glClear(GL_COLOR_BUFFER_BIT);
        glLineWidth(w);
        glBegin(GL_LINES);
        glVertex2d(p[0][0], p[0][1]);
        glVertex2d(p[1][0], p[1][1]);
        glEnd();
        read_lit(gl);
        memset(model, 0, sizeof model);
        static const double frame[4] = {0, 0, W, H};
        double t0, t1;
        ras_line l;
        if (ras_clip_line(p, frame, &t0, &t1) &&
            ras_line_pixels(p[0][0], p[0][1], p[1][0], p[1][1], w, W, H, &l, runs, W + H)) {
            for (size_t k = 0; k < l.count; k++)
                for (int32_t m = runs[k].lo; m <= runs[k].hi; m++) {
                    int32_t x = l.axis == 0 ? l.first + (int32_t)k : m;
                    int32_t y = l.axis == 0 ? m : l.first + (int32_t)k;
                    if (x >= 0 && x < W && y >= 0 && y < H)
                        model[y * W + x] = 1;
                }
        }
        char what[160];
        snprintf(what, sizeof what, "line %.9g,%.9g - %.9g,%.9g width %g", p[0][0], p[0][1], p[1][0],
                 p[1][1], w);
        if (report(what, gl, model, bad))
            bad++;
    }
    return bad;
}

static int check_points(int n, bool round, ras_run *rows)
{
    static unsigned char gl[W * H], model[W * H];
    static const int q[4] = {1, 2, 4, 4096};
    int bad = 0, skipped = 0;
    if (round)
        glEnable(GL_POINT_SMOOTH);
    for (int i = 0; i < n; i++) {
        int g = q[i % 4];
        double x = grid(10, W - 20, g), y = grid(10, H - 20, g);
        double size = next() % 2 ? 1 + next() % 12 : (1 + next() % 48) / 4.0;
        memset(model, 0, sizeof model);
        bool tie = false;
        if (round) {
            double d = size < 2 ? 2 : size, r = d / 2;
            int32_t y0;
            size_t nr = ras_point_round(x, y, d, H, &y0, rows, W);
            for (size_t k = 0; k < nr; k++)
                for (int32_t c = rows[k].lo; c <= rows[k].hi; c++)
                    model[(y0 + (int32_t)k) * W + c] = 1;
            for (int j = (int)(y - r) - 1; j <= (int)(y + r) + 1; j++)
                for (int c = (int)(x - r) - 1; c <= (int)(x + r) + 1; c++) {
                    double dx = c + 0.5 - x, dy = j + 0.5 - y;
                    tie = tie || dx * dx + dy * dy == r * r;
                }
        } else {
            int32_t x0, y0, side;
            ras_point_square(x, y, size, H, &x0, &y0, &side);
            for (int32_t j = y0; j < y0 + side; j++)
                for (int32_t c = x0; c < x0 + side; c++)
                    model[j * W + c] = 1;
        }
        if (tie) {
            skipped++;
            continue;
        }
        glClear(GL_COLOR_BUFFER_BIT);
        glPointSize((float)size);
        glBegin(GL_POINTS);
        glVertex2d(x, y);
        glEnd();
        read_lit(gl);
        char what[120];
        snprintf(what, sizeof what, "%s point %.9g,%.9g size %g", round ? "round" : "square", x, y, size);
        if (report(what, gl, model, bad))
            bad++;
    }
    glDisable(GL_POINT_SMOOTH);
    printf("%s points: %d of %d differ (%d left out: a pixel centre on the circle)\n",
           round ? "round" : "square", bad, n - skipped, skipped);
    return bad;
}

/* Lines with decimal ends under a transform GL computes in float. */
static int check_float_ends(int n, bool turned, ras_run *runs)
{
    enum { FW = 320, FH = 240 };
    static unsigned char buf[FW * FH * 4], rgb[FW * FH * 4], gl[FW * FH], model[FW * FH];
    if (!OSMesaMakeCurrent(OSMesaGetCurrentContext(), buf, GL_UNSIGNED_BYTE, FW, FH))
        return 1;
    glViewport(0, 0, FW, FH);
    glLineWidth(1);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, FW, 0, FH);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    float sx = 1, sy = 1;
    if (turned) {
        glTranslatef(6.3f, 17.7f, 0);
        glScalef(0.13f, 0.17f, 1);
        glRotatef(15, 0, 0, 1);
        sx = 0.13f, sy = 0.17f;
    }
    float proj[16], mv[16];
    glGetFloatv(GL_PROJECTION_MATRIX, proj);
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    int bad = 0;
    for (int i = 0; i < n; i++) {
        float a[3] = {(20 + (float)(next() % 2400) * 0.1f) / sx, (20 + (float)(next() % 1600) * 0.1f) / sy, 0};
        double len = 0.2 + (next() % 30) * 0.1, ang = (next() % 180) * 3.14159265358979 / 90;
        float b[3] = {(float)(a[0] + len * cos(ang) / sx), (float)(a[1] + len * sin(ang) / sy), 0};
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_LINES);
        glVertex2f(a[0], a[1]);
        glVertex2f(b[0], b[1]);
        glEnd();
        glFinish();
        glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rgb);
        for (int k = 0; k < FW * FH; k++)
            gl[k] = rgb[4 * k] > 128;
        memset(model, 0, sizeof model);
        double wa[2], wb[2];
        ras_line l;
        if (ras_window(proj, mv, FW, FH, a, wa) && ras_window(proj, mv, FW, FH, b, wb) &&
            ras_line_pixels(wa[0], wa[1], wb[0], wb[1], 1, FW, FH, &l, runs, FW + FH))
            for (size_t k = 0; k < l.count; k++)
                for (int32_t m = runs[k].lo; m <= runs[k].hi; m++) {
                    int32_t x = l.axis == 0 ? l.first + (int32_t)k : m;
                    int32_t y = l.axis == 0 ? m : l.first + (int32_t)k;
                    if (x >= 0 && x < FW && y >= 0 && y < FH)
                        model[y * FW + x] = 1;
                }
        int d = 0;
        for (int k = 0; k < FW * FH; k++)
            d += gl[k] != model[k];
        if (d) {
            if (bad < 6)
                printf("  float ends%s: line %.9g,%.9g - %.9g,%.9g: %d pixels differ\n",
                       turned ? " (turned)" : "", a[0], a[1], b[0], b[1], d);
            bad++;
        }
    }
    printf("lines with decimal ends%s: %d of %d differ\n", turned ? ", turned" : "", bad, n);
    return bad;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 4000;
    static unsigned char buf[W * H * 4];
    static ras_run runs[320 + 240];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "rascheck: no OSMesa context\n");
        return 1;
    }
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3f(1, 1, 1);
    printf("GL: %s\n", (const char *)glGetString(GL_RENDERER));
    int bad = check_lines(n, runs);
    printf("lines: %d of %d differ\n", bad, n);
    bad += check_points(n / 2, false, runs);
    bad += check_points(n / 2, true, runs);
    bad += check_float_ends(n / 2, false, runs);
    bad += check_float_ends(n / 2, true, runs);
    OSMesaDestroyContext(ctx);
    printf("%s\n", bad ? "FAIL" : "PASS");
    return bad ? 1 : 0;
}
