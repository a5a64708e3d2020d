/* rasterise.c: GL's line and point rasterisation as Mesa's llvmpipe does
 * it (rasterise.h), and the strips that cover a line's pixels.
 *
 * A line becomes a quadrilateral in 1/256-pixel fixed point: the segment
 * moved to the diamond-exit rule's ends and made w pixels tall (x-major)
 * or wide (y-major), each edge half-open as the triangle fill rule says.
 * Mesa's frame runs y down from the top with the "bottom-left" rule; the
 * pixels are found there and turned into GL's rows at the end. Held to
 * Mesa 22.3 (llvmpipe) pixel for pixel by the test rasterise-mesa
 * (tests/image/rascheck.c): random lines of widths 1 to 5 with ends on
 * whole pixels and the 1/4, 1/16 and 1/4096 grids, lines with decimal
 * ends through ras_window, square and round points.
 */
#include "rasterise.h"

#include <math.h>

#define FIX 256
/* Coordinates beyond this (pixels) are not a clipped line's: refused. */
#define RAS_COORD_MAX 1048576.0

/* Mesa's util_iround: half away from zero, in float. */
static int64_t round_away(float f) { return f >= 0 ? (int64_t)(f + 0.5f) : (int64_t)(f - 0.5f); }

static int64_t snap(float a) { return round_away((float)FIX * a); }

static bool nonneg(float x) { return x >= 0; }

static float frac_pos(float f) { return f - floorf(f); }

static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

typedef struct quad {
    int64_t x[4], y[4]; /* fixed point, Mesa's frame, half a pixel shifted */
    int axis;           /* 0 x-major, 1 y-major */
} quad;

/* Whether the diamond-exit rule draws the first pixel (start) and the last
 * pixel (end) of the line, the minor axis being b and the major a: d are
 * the ends' offsets from their pixel centres, dm the ends' difference
 * (first minus second), slope minor per major. Mesa's tests, x-major
 * written with a = x; y-major swaps the roles and one sign convention. */
typedef struct ends {
    bool start, end;
} ends;

static ends diamond_x(float x1d, float y1d, float x2d, float y2d, float y1, float y2, float dx,
                      float dy)
{
    float m = dy / dx;
    ends e;
    if (fabsf(x1d) + fabsf(y1d) < 0.5f)
        e.start = true;
    else if (nonneg(x1d) == nonneg(-dx))
        e.start = false;
    else if (nonneg(-y1d) != nonneg(dy))
        e.start = true;
    else {
        float yi = frac_pos(y1) + x1d * m;
        e.start = yi < 1.0f && yi > 0.0f;
    }
    if (fabsf(x2d) + fabsf(y2d) < 0.5f)
        e.end = false;
    else if (nonneg(x2d) != nonneg(-dx))
        e.end = false;
    else if (nonneg(-y2d) == nonneg(dy))
        e.end = true;
    else {
        float yi = frac_pos(y2) + x2d * m;
        e.end = yi < 1.0f && yi > 0.0f;
    }
    return e;
}

static ends diamond_y(float x1d, float y1d, float x2d, float y2d, float x1, float x2, float dx,
                      float dy)
{
    float m = dx / dy;
    ends e;
    if (fabsf(x1d) + fabsf(y1d) < 0.5f)
        e.start = true;
    else if (nonneg(-y1d) == nonneg(dy))
        e.start = false;
    else if (nonneg(x1d) != nonneg(-dx))
        e.start = true;
    else {
        float xi = frac_pos(x1) + y1d * m;
        e.start = xi < 1.0f && xi > 0.0f;
    }
    if (fabsf(x2d) + fabsf(y2d) < 0.5f)
        e.end = false;
    else if (nonneg(-y2d) != nonneg(dy))
        e.end = false;
    else if (nonneg(x2d) == nonneg(-dx))
        e.end = true;
    else {
        float xi = frac_pos(x2) + y2d * m;
        e.end = xi < 1.0f && xi >= 0.0f;
    }
    return e;
}

/* The line's quadrilateral, ends (a, b) in Mesa's frame. The ends move by
 * half a pixel along the major axis where the diamond-exit rule and the
 * half-open quad disagree about the first or last pixel. */
static bool line_quad(const float a[2], const float b[2], int64_t wfix, quad *q)
{
    const float *v1 = a, *v2 = b;
    float dx = v1[0] - v2[0], dy = v1[1] - v2[1];
    if (dx * dx + dy * dy == 0)
        return false;
    float x1d = v1[0] - floorf(v1[0]) - 0.5f, y1d = v1[1] - floorf(v1[1]) - 0.5f;
    float x2d = v2[0] - floorf(v2[0]) - 0.5f, y2d = v2[1] - floorf(v2[1]) - 0.5f;
    float off[2] = {0, 0}, off_end[2] = {0, 0}; /* added to v1 and v2 (after the swap) */
    if (fabsf(dx) >= fabsf(dy)) {
        float m = dy / dx;
        if (y2d == -0.5f && dy < 0)
            y2d = 0.5f;
        ends e = diamond_x(x1d, y1d, x2d, y2d, v1[1], v2[1], dx, dy);
        bool will_start = nonneg(-x1d) != nonneg(dx);
        bool will_end = nonneg(x2d) == nonneg(-dx) || x2d == 0;
        if (dx < 0) { /* v1 left of v2: draw from v2 */
            v1 = b, v2 = a;
            if (will_start != e.start)
                off_end[0] = -x1d - 0.5f;
            if (will_end != e.end)
                off[0] = -x2d - 0.5f;
        } else {
            if (will_start != e.start)
                off[0] = -x1d + 0.5f;
            if (will_end != e.end)
                off_end[0] = -x2d + 0.5f;
        }
        off[1] = off[0] * m;
        off_end[1] = off_end[0] * m;
        int64_t xa = snap(v1[0] + off[0] - 0.5f), xb = snap(v2[0] + off_end[0] - 0.5f);
        int64_t ya = snap(v1[1] + off[1] - 0.5f), yb = snap(v2[1] + off_end[1] - 0.5f);
        q->x[0] = q->x[3] = xa;
        q->x[1] = q->x[2] = xb;
        q->y[0] = ya - wfix / 2;
        q->y[1] = yb - wfix / 2;
        q->y[2] = yb + wfix / 2;
        q->y[3] = ya + wfix / 2;
        q->axis = 0;
    } else {
        float m = dx / dy;
        if (x2d == -0.5f && dx < 0)
            x2d = 0.5f;
        ends e = diamond_y(x1d, y1d, x2d, y2d, v1[0], v2[0], dx, dy);
        bool will_start = nonneg(y1d) == nonneg(dy);
        bool will_end = nonneg(-y2d) == nonneg(dy) || y2d == 0;
        if (dy > 0) { /* v1 below v2 in Mesa's frame: draw from v2 */
            v1 = b, v2 = a;
            if (will_start != e.start)
                off_end[1] = -y1d + 0.5f;
            if (will_end != e.end)
                off[1] = -y2d + 0.5f;
        } else {
            if (will_start != e.start)
                off[1] = -y1d - 0.5f;
            if (will_end != e.end)
                off_end[1] = -y2d - 0.5f;
        }
        off[0] = off[1] * m;
        off_end[0] = off_end[1] * m;
        int64_t xa = snap(v1[0] + off[0] - 0.5f), xb = snap(v2[0] + off_end[0] - 0.5f);
        int64_t ya = snap(v1[1] + off[1] - 0.5f), yb = snap(v2[1] + off_end[1] - 0.5f);
        q->x[0] = xa - wfix / 2;
        q->x[1] = xb - wfix / 2;
        q->x[2] = xb + wfix / 2;
        q->x[3] = xa + wfix / 2;
        q->y[0] = q->y[3] = ya;
        q->y[1] = q->y[2] = yb;
        q->axis = 1;
    }
    return true;
}

typedef struct edges {
    int64_t dcdx[4], dcdy[4], c[4];
} edges;

/* Edge functions, positive inside; an edge's own pixels are in when it is
 * a left edge or a horizontal one running right (the bottom-left rule). */
static void quad_edges(const quad *q, edges *e)
{
    for (int k = 0; k < 4; k++) {
        int n = (k + 1) % 4;
        e->dcdy[k] = q->x[k] - q->x[n];
        e->dcdx[k] = q->y[k] - q->y[n];
        e->c[k] = e->dcdx[k] * q->x[k] - e->dcdy[k] * q->y[k];
        if (e->dcdx[k] < 0 || (e->dcdx[k] == 0 && e->dcdy[k] < 0))
            e->c[k]++;
    }
}

/* The minor indices (Mesa's) of the pixels inside the quad at major
 * index k. Pixel (i, j)'s centre sits at (i, j) * FIX once the quad is
 * shifted by half a pixel; each edge's test c - dcdx X + dcdy Y > 0 there
 * is linear in the minor index, so it bounds it on one side, or holds or
 * fails for the whole column (row). Empty when *lo > *hi. */
static void minor_span(const edges *e, int ax, int64_t k, int64_t *lo, int64_t *hi)
{
    *lo = INT64_MIN / 4;
    *hi = INT64_MAX / 4;
    for (int n = 0; n < 4; n++) {
        /* a * j > b, j the minor index */
        int64_t a, b;
        if (ax == 0) {
            a = e->dcdy[n] * FIX;
            b = e->dcdx[n] * k * FIX - e->c[n];
        } else {
            a = -e->dcdx[n] * FIX;
            b = -e->dcdy[n] * k * FIX - e->c[n];
        }
        if (a > 0) {
            int64_t j = floor_div(b, a) + 1;
            *lo = j > *lo ? j : *lo;
        } else if (a < 0) {
            int64_t j = -floor_div(b, -a) - 1; /* j < b / a */
            *hi = j < *hi ? j : *hi;
        } else if (b >= 0) {
            *lo = 1, *hi = 0;
            return;
        }
    }
}

static int64_t min4(const int64_t v[4])
{
    int64_t m = v[0];
    for (int k = 1; k < 4; k++)
        m = v[k] < m ? v[k] : m;
    return m;
}

static int64_t max4(const int64_t v[4])
{
    int64_t m = v[0];
    for (int k = 1; k < 4; k++)
        m = v[k] > m ? v[k] : m;
    return m;
}

bool ras_line_pixels(double x0, double y0, double x1, double y1, double width, int32_t frame_w,
                     int32_t frame_h, ras_line *out, ras_run *runs, size_t max)
{
    out->count = 0;
    double c[4] = {x0, y0, x1, y1};
    for (int k = 0; k < 4; k++)
        if (!(fabs(c[k]) < RAS_COORD_MAX))
            return false;
    if (frame_w <= 0 || frame_h <= 0)
        return false;
    /* Mesa: the width at least 1, rounded half away from zero. */
    float wf = (float)width;
    int64_t wpix = round_away(wf > 1 ? wf : 1.0f);
    if (wpix > 255)
        wpix = 255; /* GL_ALIASED_LINE_WIDTH_RANGE's top in Mesa */
    /* Mesa's frame: flipped in double, then rounded once (a caller that
     * holds Mesa's own float y there gets it back exactly). */
    float a[2] = {(float)x0, (float)((double)frame_h - y0)};
    float b[2] = {(float)x1, (float)((double)frame_h - y1)};
    quad q;
    if (!line_quad(a, b, wpix * FIX, &q))
        return false;
    edges e;
    quad_edges(&q, &e);
    int ax = q.axis;
    const int64_t *maj = ax == 0 ? q.x : q.y;
    int64_t lo = floor_div(min4(maj), FIX) - 1, hi = floor_div(max4(maj), FIX) + 1;
    int64_t size = ax == 0 ? frame_w : frame_h;
    /* Mesa's rows count from the top: GL's major index is size - 1 - it. */
    int64_t glo = ax == 0 ? lo : size - 1 - hi, ghi = ax == 0 ? hi : size - 1 - lo;
    glo = glo < 0 ? 0 : glo;
    ghi = ghi > size - 1 ? size - 1 : ghi;
    if (glo > ghi)
        return false;
    if ((uint64_t)(ghi - glo + 1) > max)
        return false;
    size_t count = 0;
    int32_t first = -1;
    for (int64_t g = glo; g <= ghi; g++) {
        int64_t k = ax == 0 ? g : size - 1 - g; /* Mesa's index */
        int64_t lo_m, hi_m;
        minor_span(&e, ax, k, &lo_m, &hi_m);
        int32_t rlo = INT32_MAX, rhi = INT32_MIN;
        if (lo_m <= hi_m) {
            /* GL's minor index: rows flip, columns do not. */
            int64_t a0 = ax == 0 ? frame_h - 1 - hi_m : lo_m, a1 = ax == 0 ? frame_h - 1 - lo_m : hi_m;
            if (a0 >= INT32_MIN && a1 <= INT32_MAX)
                rlo = (int32_t)a0, rhi = (int32_t)a1;
        }
        if (rlo > rhi) {
            if (first >= 0)
                runs[count++] = (ras_run){1, 0};
            continue;
        }
        if (first < 0)
            first = (int32_t)g;
        runs[count++] = (ras_run){rlo, rhi};
    }
    while (count > 0 && runs[count - 1].lo > runs[count - 1].hi)
        count--;
    if (count == 0)
        return false;
    out->axis = ax;
    out->first = first;
    out->count = count;
    return true;
}

/* a0 v0 + a1 v1 + a2 v2 + a3 v3 in float, left to right, one operation a
 * statement (clang fuses a multiply and an add within one). */
static float dot4_f32(float a0, float a1, float a2, float a3, const float v[4])
{
    float s = a0 * v[0], t = a1 * v[1];
    s = s + t;
    t = a2 * v[2];
    s = s + t;
    t = a3 * v[3];
    s = s + t;
    return s;
}

bool ras_window(const float proj[16], const float mv[16], int32_t w, int32_t h,
                const float obj[3], double out[2])
{
    float mvp[16], c[4], one[4] = {obj[0], obj[1], obj[2], 1};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            mvp[4 * j + i] = dot4_f32(proj[i], proj[4 + i], proj[8 + i], proj[12 + i], &mv[4 * j]);
    for (int i = 0; i < 4; i++)
        c[i] = dot4_f32(mvp[i], mvp[4 + i], mvp[8 + i], mvp[12 + i], one);
    if (!(c[3] > 0))
        return false;
    float inv = 1.0f / c[3];
    float sx = (float)w * 0.5f, sy = -(float)h * 0.5f, ty = (float)h * 0.5f;
    float x = c[0] * inv, y = c[1] * inv;
    x = fmaf(x, sx, sx);
    y = fmaf(y, sy, ty);
    if (!isfinite(x) || !isfinite(y))
        return false;
    out[0] = x;
    out[1] = (double)h - (double)y;
    return true;
}

bool ras_clip_line(double p[2][2], const double r[4], double *t0, double *t1)
{
    double ta = 0, tb = 1, d[2] = {p[1][0] - p[0][0], p[1][1] - p[0][1]};
    int side_a = -1, side_b = -1; /* the side (index into r) each end lands on */
    for (int s = 0; s < 4; s++) {
        int ax = s % 2;
        double sgn = s < 2 ? 1 : -1; /* keep sgn * (p - r[s]) >= 0 */
        double num = sgn * (p[0][ax] - r[s]), den = sgn * d[ax];
        if (den == 0) {
            if (num < 0)
                return false;
            continue;
        }
        double t = -num / den;
        if (den > 0 && t > ta) {
            ta = t;
            side_a = s;
        } else if (den < 0 && t < tb) {
            tb = t;
            side_b = s;
        }
    }
    if (!(ta < tb))
        return false;
    double q[2][2];
    for (int ax = 0; ax < 2; ax++) {
        q[0][ax] = side_a >= 0 ? p[0][ax] + d[ax] * ta : p[0][ax];
        q[1][ax] = side_b >= 0 ? p[0][ax] + d[ax] * tb : p[1][ax];
    }
    if (side_a >= 0)
        q[0][side_a % 2] = r[side_a];
    if (side_b >= 0)
        q[1][side_b % 2] = r[side_b];
    for (int k = 0; k < 2; k++)
        p[k][0] = q[k][0], p[k][1] = q[k][1];
    *t0 = ta;
    *t1 = tb;
    return true;
}

/* Where a strip's lower edge goes in the gap between the unlit and the lit
 * centres (and its upper edge in the other), as fractions of the gap: off
 * the middle by amounts no simple fraction makes, so that the diagonal
 * of a strip's two triangles does not pass through a pixel centre. */
#define PIECE_LO 0.4627
#define PIECE_HI 0.4519

size_t ras_line_pieces(const ras_line *l, const ras_run *runs, double slope, ras_piece *out,
                       size_t max)
{
    size_t n = 0;
    const double gap_min = RAS_MARGIN / PIECE_HI;
    size_t k = 0;
    while (k < l->count) {
        if (runs[k].lo > runs[k].hi) {
            k++;
            continue;
        }
        /* e: a run's end centres less slope * its centre, which a strip
         * of that slope must keep within its edges. */
        double lo_min = INFINITY, lo_max = -INFINITY, hi_min = INFINITY, hi_max = -INFINITY;
        size_t j = k;
        for (; j < l->count && runs[j].lo <= runs[j].hi; j++) {
            double t = (double)(l->first + (int32_t)j) + 0.5;
            double elo = runs[j].lo + 0.5 - slope * t, ehi = runs[j].hi + 0.5 - slope * t;
            double nlo_min = fmin(lo_min, elo), nlo_max = fmax(lo_max, elo);
            double nhi_min = fmin(hi_min, ehi), nhi_max = fmax(hi_max, ehi);
            if (j > k && (1 - (nlo_max - nlo_min) < gap_min || 1 - (nhi_max - nhi_min) < gap_min))
                break;
            lo_min = nlo_min, lo_max = nlo_max, hi_min = nhi_min, hi_max = nhi_max;
        }
        if (n >= max)
            return 0;
        double glo = 1 - (lo_max - lo_min), ghi = 1 - (hi_max - hi_min);
        out[n].a = l->first + (int32_t)k;
        out[n].b = l->first + (int32_t)j;
        out[n].lo = lo_max - 1 + glo * PIECE_LO;
        out[n].hi = hi_min + 1 - ghi * PIECE_HI;
        n++;
        k = j;
    }
    return n;
}

void ras_point_square(double x, double y, double size, int32_t frame_h, int32_t *x0, int32_t *y0,
                      int32_t *n)
{
    /* Mesa's legacy points (GL 2.1 3.3.1): the size rounded (a half down),
     * at least 1; an odd size centred on the pixel the point is in, an
     * even one on the nearest pixel corner. Mesa's frame runs down: its
     * "bottom-left" rule takes a point on a pixel's top edge into it. */
    float sz = (float)size;
    int64_t w = (snap(sz > 0 ? sz : 0) + FIX / 2 - 1) & ~(int64_t)(FIX - 1);
    if (w < FIX)
        w = FIX;
    int64_t side = w / FIX;
    int64_t xs = snap((float)x), ys = snap((float)((double)frame_h - y)) - 1;
    int64_t bx, by;
    if (side == 1) {
        bx = floor_div(xs, FIX);
        by = floor_div(ys, FIX);
    } else if (side % 2) {
        bx = floor_div(xs, FIX) - (side - 1) / 2;
        by = floor_div(ys, FIX) - (side - 1) / 2;
    } else {
        bx = floor_div(xs + FIX / 2, FIX) - side / 2;
        by = floor_div(ys + FIX / 2, FIX) - side / 2;
    }
    *x0 = (int32_t)bx;
    *y0 = (int32_t)(frame_h - by - side); /* GL's lowest row */
    *n = (int32_t)side;
}

size_t ras_point_round(double x, double y, double d, int32_t frame_h, int32_t *y0,
                       ras_run *rows, size_t max)
{
    (void)frame_h;
    if (!(d > 0) || !(fabs(x) < RAS_COORD_MAX) || !(fabs(y) < RAS_COORD_MAX) || d > 4096)
        return 0;
    double r = d / 2;
    /* The square's pixels: Mesa snaps its corners and takes the left and
     * bottom edges in (GL's frame). */
    double xa = (double)snap((float)(x - r)) / FIX, xb = (double)snap((float)(x + r)) / FIX;
    double ya = (double)snap((float)(y - r)) / FIX, yb = (double)snap((float)(y + r)) / FIX;
    int64_t i0 = (int64_t)ceil(xa - 0.5), i1 = (int64_t)ceil(xb - 0.5) - 1;
    int64_t j0 = (int64_t)ceil(ya - 0.5), j1 = (int64_t)ceil(yb - 0.5) - 1;
    size_t n = 0;
    int64_t first = 0;
    for (int64_t j = j0; j <= j1; j++) {
        double dy = (double)j + 0.5 - y;
        int32_t lo = INT32_MAX, hi = INT32_MIN;
        for (int64_t i = i0; i <= i1; i++) {
            double dx = (double)i + 0.5 - x;
            if (dx * dx + dy * dy <= r * r) {
                lo = (int32_t)i < lo ? (int32_t)i : lo;
                hi = (int32_t)i > hi ? (int32_t)i : hi;
            }
        }
        if (lo > hi) {
            if (n > 0)
                break; /* a disc's rows are contiguous */
            continue;
        }
        if (n == 0)
            first = j;
        if (n >= max)
            return 0;
        rows[n++] = (ras_run){lo, hi};
    }
    *y0 = (int32_t)first;
    return n;
}
