/* povwrite_pstipple.c: polygon stipple (interp_pstipple.c) as a clipped_by.
 *
 * The kept set is an isosurface used only for its inside test (a clipped
 * surface asks "inside?" at each hit, never looks for a root), so the cells
 * are crisp: a function of the eye-space point that projects it through
 * the frame's camera to its window pixel (x, y) and reads bit (x mod 32,
 * y mod 32) of the mask. A hit on an unset pixel is dropped and the ray
 * goes on, so the pixel shows what lies behind, as GL leaves it. Exact
 * where the camera's rays run through pixel centres (no antialiasing);
 * reflected or refracted rays see the pattern from the camera's view. */
#include "povwrite_pstipple.h"

#include <math.h>
#include <stdio.h>

/* A double as the sum of two singles (outbuf's numbers are locale-free
 * singles): about 1e-14 relative, far below a pixel at any image size. */
static void put_num(outbuf *ob, double v)
{
    if (!isfinite(v) || fabs(v) > 1e30)
        v = 0;
    float hi = (float)v, lo = (float)(v - (double)hi);
    outbuf_putc(ob, '(');
    outbuf_f32(ob, hi);
    if (lo != 0) {
        if (!(lo < 0))
            outbuf_putc(ob, '+');
        outbuf_f32(ob, lo);
    }
    outbuf_putc(ob, ')');
}

/* Rows lo..hi-1 of the mask as 32-bit numbers (bit i: window x mod 32 = i),
 * chosen by j through a tree of select()s. */
static void put_rows(outbuf *ob, const uint8_t *m, int lo, int hi)
{
    if (hi - lo == 1) {
        uint32_t r = 0;
        for (int i = 0; i < 32; i++)
            if ((m[lo * 4 + i / 8] >> (7 - i % 8)) & 1)
                r |= 1u << i;
        outbuf_u64(ob, r);
        return;
    }
    int mid = (lo + hi) / 2;
    outbuf_puts(ob, "select(J-");
    outbuf_u64(ob, (uint64_t)mid);
    outbuf_putc(ob, ',');
    put_rows(ob, m, lo, mid);
    outbuf_putc(ob, ',');
    put_rows(ob, m, mid, hi);
    outbuf_putc(ob, ')');
}

/* row . (p - location) / div, over the function's x, y, z. */
static void put_coord(outbuf *ob, const scene_camera *cam, const double row[3], double div)
{
    outbuf_putc(ob, '(');
    put_num(ob, row[0] / div);
    outbuf_puts(ob, "*(x-");
    put_num(ob, cam->location[0]);
    outbuf_puts(ob, ")+");
    put_num(ob, row[1] / div);
    outbuf_puts(ob, "*(y-");
    put_num(ob, cam->location[1]);
    outbuf_puts(ob, ")+");
    put_num(ob, row[2] / div);
    outbuf_puts(ob, "*(z-");
    put_num(ob, cam->location[2]);
    outbuf_puts(ob, "))");
}

void povwrite_pstipple(outbuf *ob, const scene *s, const scene_look *look)
{
    const scene_camera *cam = &s->camera;
    const uint8_t *mask = scene_pstipple_mask(s, look->pstipple);
    if (!mask || cam->width <= 0 || cam->height <= 0)
        return;
    /* p - location = t direction + a right + b up: the rows of the inverse
     * of the matrix whose columns are direction, right, up. */
    const double *c0 = cam->direction, *c1 = cam->right, *c2 = cam->up;
    double inv[3][3] = {
        {c1[1] * c2[2] - c1[2] * c2[1], c1[2] * c2[0] - c1[0] * c2[2], c1[0] * c2[1] - c1[1] * c2[0]},
        {c2[1] * c0[2] - c2[2] * c0[1], c2[2] * c0[0] - c2[0] * c0[2], c2[0] * c0[1] - c2[1] * c0[0]},
        {c0[1] * c1[2] - c0[2] * c1[1], c0[2] * c1[0] - c0[0] * c1[2], c0[0] * c1[1] - c0[1] * c1[0]},
    };
    double det = c0[0] * inv[0][0] + c0[1] * inv[0][1] + c0[2] * inv[0][2];
    if (!(fabs(det) > 1e-300))
        return;
    /* Named by the mask and origin (all the function depends on in a
     * frame's file), declared once: POV-Ray refuses to redeclare one. */
    uint64_t hash = 1469598103934665603ull;
    for (int i = 0; i < 130; i++) {
        hash ^= i < 128 ? mask[i] : look->pstipple_org[i - 128];
        hash *= 1099511628211ull;
    }
    char name[40];
    snprintf(name, sizeof name, "rgl_pst%016llx", (unsigned long long)hash);
    outbuf_puts(ob, "#ifndef(");
    outbuf_puts(ob, name);
    outbuf_puts(ob, ")\n#declare ");
    outbuf_puts(ob, name);
    outbuf_puts(ob, "_row=function(J){");
    put_rows(ob, mask, 0, 32);
    outbuf_puts(ob, "}\n#declare ");
    outbuf_puts(ob, name);
    outbuf_puts(ob, "=function(PX,PY){1-mod(floor(");
    outbuf_puts(ob, name);
    outbuf_puts(ob, "_row(mod(mod(PY,32)+32,32))/pow(2,mod(mod(PX,32)+32,32))),2)}\n#end\n");
    outbuf_puts(ob, "clipped_by{isosurface{function{");
    outbuf_puts(ob, name);
    outbuf_putc(ob, '(');
    bool persp = cam->kind != SCENE_CAMERA_ORTHOGRAPHIC;
    for (int k = 1; k <= 2; k++) {
        /* the pixel's column (k 1) or row (k 2) in the window */
        int size = k == 1 ? cam->width : cam->height;
        if (k == 2)
            outbuf_putc(ob, ',');
        outbuf_puts(ob, "floor((");
        put_coord(ob, cam, inv[k], persp ? (det > 0 ? 1 : -1) : det);
        if (persp) {
            outbuf_puts(ob, "/max(");
            put_coord(ob, cam, inv[0], det > 0 ? 1 : -1);
            outbuf_puts(ob, ",1e-300)");
        }
        outbuf_puts(ob, "+0.5)*");
        outbuf_u64(ob, (uint64_t)size);
        outbuf_puts(ob, ")+");
        outbuf_u64(ob, look->pstipple_org[k - 1]);
    }
    outbuf_puts(ob, ")}threshold 0.5 contained_by{box{-1e9,1e9}}}}\n");
}
