/* povwrite_solid.c: GLU/GLUT solids as POV-Ray solids (povwrite_solid.h).
 *
 * Each solid is written in GL's object space of the shape (scene.h gives
 * the axis conventions) and placed with its object -> eye matrix; POV-Ray's
 * torus lies in its xz plane, so it turns into GL's xy plane first. The
 * teapot is one declared mesh of Newell's 32 patches (RGL_Teapot), written
 * once per scene and scaled by each call's size. The surface takes the
 * unlit texture of its colour, or the lit one, with the fog layer on top
 * when fogged (docs/mapping.md). */
#include "povwrite_solid.h"

#include <math.h>

#include "povwrite_clip.h"
#include "povwrite_pstipple.h"
#include "povwrite_fogsec.h"
#include "teapot.h"
#include "teapot_mesh.h"

static void put_xyz(outbuf *ob, double x, double y, double z)
{
    outbuf_putc(ob, '<');
    outbuf_f32(ob, (float)x);
    outbuf_putc(ob, ',');
    outbuf_f32(ob, (float)y);
    outbuf_putc(ob, ',');
    outbuf_f32(ob, (float)z);
    outbuf_putc(ob, '>');
}

static bool finite_pos(double v) { return isfinite(v) && v > 0 && (float)v > 0 && isfinite((float)v); }

static void put_matrix(outbuf *ob, const mat4 *to_eye)
{
    static const int idx[12] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14};
    outbuf_puts(ob, " matrix<");
    for (int i = 0; i < 12; i++) {
        if (i)
            outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)to_eye->m[idx[i]]);
    }
    outbuf_putc(ob, '>');
}

static void write_solid(outbuf *ob, const scene *s, const scene_solid *so, const povlight *pl)
{
    const double *p = so->params;
    if (!mat4_finite(&so->to_eye) || !mat4_affine(&so->to_eye))
        return;
    for (int k = 0; k < 4; k++)
        if (!isfinite(so->color[k]))
            return;
    /* Fog is a layer over the surface, as on meshes (povwrite_light.c),
     * in the solid's own space: its texture is placed by the same matrix. */
    if (so->look.fog)
        povfog_declare(pl, ob, "rgl_fog", &so->to_eye, &so->look);
    switch (so->kind) {
    case SCENE_SOLID_SPHERE:
        if (!finite_pos(p[0]))
            return;
        outbuf_puts(ob, "sphere{<0,0,0>,");
        outbuf_f32(ob, (float)p[0]);
        break;
    case SCENE_SOLID_BOX:
        if (!finite_pos(p[0]) || !finite_pos(p[1]) || !finite_pos(p[2]))
            return;
        outbuf_puts(ob, "box{");
        put_xyz(ob, -p[0], -p[1], -p[2]);
        outbuf_putc(ob, ',');
        put_xyz(ob, p[0], p[1], p[2]);
        break;
    case SCENE_SOLID_CONE: {
        double b = p[0], t = p[1], h = p[2];
        if (!finite_pos(h) || !isfinite(b) || !isfinite(t) || b < 0 || t < 0 || (b == 0 && t == 0))
            return;
        if ((float)b == (float)t) {
            outbuf_puts(ob, "cylinder{<0,0,0>,");
            put_xyz(ob, 0, 0, h);
            outbuf_putc(ob, ',');
            outbuf_f32(ob, (float)b);
        } else {
            outbuf_puts(ob, "cone{<0,0,0>,");
            outbuf_f32(ob, (float)b);
            outbuf_putc(ob, ',');
            put_xyz(ob, 0, 0, h);
            outbuf_putc(ob, ',');
            outbuf_f32(ob, (float)t);
        }
        if (so->open)
            outbuf_puts(ob, " open");
        break;
    }
    case SCENE_SOLID_TORUS:
        if (!finite_pos(p[0]) || !finite_pos(p[1]) || !(p[0] > p[1]))
            return;
        outbuf_puts(ob, "torus{");
        outbuf_f32(ob, (float)p[0]);
        outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)p[1]);
        outbuf_puts(ob, " rotate<90,0,0>");
        break;
    case SCENE_SOLID_DISC:
        if (!finite_pos(p[0]) || !isfinite(p[1]) || p[1] < 0 || !(p[1] < p[0]))
            return;
        outbuf_puts(ob, "disc{<0,0,0>,<0,0,1>,");
        outbuf_f32(ob, (float)p[0]);
        if (p[1] > 0) {
            outbuf_putc(ob, ',');
            outbuf_f32(ob, (float)p[1]);
        }
        break;
    case SCENE_SOLID_TEAPOT:
        if (!finite_pos(p[0]))
            return;
        outbuf_puts(ob, "object{RGL_Teapot scale ");
        outbuf_f32(ob, (float)p[0]);
        break;
    default:
        return;
    }
    if (povlight_special(&so->look)) { /* lit, transparent or fogged */
        outbuf_puts(ob, "\n ");
        povlight_texture(pl, ob, &so->look, so->color, 0);
        if (so->look.fog)
            outbuf_puts(ob, " texture{rgl_fog}");
    } else {
        outbuf_puts(ob, "\n texture{pigment{rgb");
        put_xyz(ob, so->color[0], so->color[1], so->color[2]);
        outbuf_puts(ob, "}}");
    }
    put_matrix(ob, &so->to_eye);
    povwrite_scissor(ob, s, &so->look);
    povwrite_clip(ob, s, &so->look);
    povwrite_stencil(ob, s, &so->look);
    povwrite_pstipple(ob, s, &so->look);
    outbuf_puts(ob, "}\n");
}

/* Each patch is cut into 2^TEAPOT_STEPS x 2^TEAPOT_STEPS cells: 32 x 32
 * stay within 0.001 x size of the true surface (16 x 16: 0.004; GL's 7 x 7:
 * 0.019). One mesh2 whose patches share their seam vertices
 * (teapot_mesh.c): bicubic_patch cuts each patch on its own and let rays
 * slip through the seams. POV-Ray keeps one copy of a mesh for every
 * object{} placing it (docs/mapping.md). */
#define TEAPOT_STEPS 5

static void put_fxyz(outbuf *ob, const float v[3]) { put_xyz(ob, v[0], v[1], v[2]); }

/* The patches as bicubic_patch objects: when the mesh cannot be built. */
static void teapot_patches(outbuf *ob)
{
    outbuf_puts(ob, "#declare RGL_Teapot=union{\n");
    for (int p = 0; p < TEAPOT_PATCHES; p++) {
        double cp[16][3];
        teapot_control_points(p, cp);
        outbuf_puts(ob, "bicubic_patch{type 0 flatness 0 u_steps ");
        outbuf_u64(ob, TEAPOT_STEPS);
        outbuf_puts(ob, " v_steps ");
        outbuf_u64(ob, TEAPOT_STEPS);
        for (int k = 0; k < 16; k++) {
            if (k)
                outbuf_putc(ob, ',');
            if (k % 4 == 0)
                outbuf_putc(ob, '\n');
            put_xyz(ob, cp[k][0], cp[k][1], cp[k][2]);
        }
        outbuf_puts(ob, "}\n");
    }
    outbuf_puts(ob, "}\n");
}

void povwrite_solid_declares(outbuf *ob, const scene *s)
{
    bool any = false;
    for (size_t i = 0; i < s->nsolids && !any; i++)
        any = s->solids[i].kind == SCENE_SOLID_TEAPOT;
    if (!any)
        return;
    teapot_mesh m;
    if (teapot_mesh_build(&m, 1 << TEAPOT_STEPS) != 0) {
        teapot_patches(ob);
        return;
    }
    outbuf_puts(ob, "#declare RGL_Teapot=mesh2{\nvertex_vectors{");
    outbuf_u64(ob, m.nverts);
    for (size_t v = 0; v < m.nverts; v++) {
        outbuf_puts(ob, v % 4 ? "," : ",\n");
        put_fxyz(ob, m.pos[v]);
    }
    outbuf_puts(ob, "}\nnormal_vectors{");
    outbuf_u64(ob, m.nverts);
    for (size_t v = 0; v < m.nverts; v++) {
        outbuf_puts(ob, v % 4 ? "," : ",\n");
        put_fxyz(ob, m.normal[v]);
    }
    outbuf_puts(ob, "}\nface_indices{");
    outbuf_u64(ob, m.ntris);
    for (size_t t = 0; t < m.ntris; t++) {
        outbuf_puts(ob, t % 8 ? ",<" : ",\n<");
        for (int k = 0; k < 3; k++) {
            if (k)
                outbuf_putc(ob, ',');
            outbuf_u64(ob, m.tri[t][k]);
        }
        outbuf_putc(ob, '>');
    }
    outbuf_puts(ob, "}\n}\n");
    teapot_mesh_free(&m);
}

void povwrite_scissor(outbuf *ob, const scene *s, const scene_look *look)
{
    const scene_camera *cam = &s->camera;
    if (!look->scissored || cam->width <= 0 || cam->height <= 0)
        return;
    const int32_t *b = look->scissor;
    /* Image coordinates in [-1/2, 1/2] (scene_camera) of the edges. */
    double u[2] = {(double)b[0] / cam->width - 0.5, ((double)b[0] + b[2]) / cam->width - 0.5};
    double v[2] = {(double)b[1] / cam->height - 0.5, ((double)b[1] + b[3]) / cam->height - 0.5};
    double uc = (u[0] + u[1]) / 2, vc = (v[0] + v[1]) / 2;
    bool persp = cam->kind != SCENE_CAMERA_ORTHOGRAPHIC;
    double inside[3];
    for (int k = 0; k < 3; k++)
        inside[k] = cam->location[k] + cam->direction[k] + uc * cam->right[k] + vc * cam->up[k];
    outbuf_puts(ob, "clipped_by{");
    for (int e = 0; e < 4; e++) {
        bool vertical = e < 2; /* left and right edges: a u; else a v */
        double t = vertical ? u[e] : v[e - 2];
        const double *along = vertical ? cam->right : cam->up;
        const double *other = vertical ? cam->up : cam->right;
        /* The plane holds the edge's rays: from the eye along direction +
         * t along (perspective), or from location + t along, along
         * direction (orthographic); and the other image axis. */
        double p0[3], ray[3], n[3];
        for (int k = 0; k < 3; k++) {
            p0[k] = cam->location[k] + (persp ? 0 : t * along[k]);
            ray[k] = cam->direction[k] + (persp ? t * along[k] : 0);
        }
        cross3(ray, other, n);
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 0) || !isfinite(len))
            continue;
        double d = 0, side = 0;
        for (int k = 0; k < 3; k++) {
            n[k] /= len;
            d += n[k] * p0[k];
        }
        for (int k = 0; k < 3; k++)
            side += n[k] * inside[k];
        if (side > d) { /* POV-Ray keeps n.p < d */
            for (int k = 0; k < 3; k++)
                n[k] = -n[k];
            d = -d;
        }
        outbuf_puts(ob, "plane{");
        put_xyz(ob, n[0], n[1], n[2]);
        outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)d);
        outbuf_putc(ob, '}');
    }
    outbuf_puts(ob, "}\n");
}

void povwrite_names(outbuf *ob, const scene *s, uint32_t names)
{
    uint32_t n;
    const uint32_t *v = scene_names(s, names, &n);
    if (!v)
        return;
    outbuf_puts(ob, "// names:");
    for (uint32_t i = 0; i < n; i++) {
        outbuf_putc(ob, ' ');
        outbuf_u64(ob, v[i]);
    }
    outbuf_putc(ob, '\n');
}

void povwrite_solids(outbuf *ob, const scene *s, const povlight *pl)
{
    for (size_t i = 0; i < s->nsolids; i++) {
        if (!povlight_in_pass(pl, &s->solids[i].look))
            continue;
        povwrite_names(ob, s, s->solids[i].look.names);
        write_solid(ob, s, &s->solids[i], pl);
    }
}

bool povwrite_solid_anchor(const scene *s, float out[3])
{
    for (size_t i = 0; i < s->nsolids; i++) {
        const double *m = s->solids[i].to_eye.m;
        float c[3] = {(float)m[12], (float)m[13], (float)m[14]};
        if (isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2])) {
            for (int k = 0; k < 3; k++)
                out[k] = c[k];
            return true;
        }
    }
    return false;
}
