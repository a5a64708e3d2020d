/* interp_sprite.c: textured points and point sprites (GL 2.1 3.3, 3.3.1).
 *
 * GL textures a point as any fragment: without point sprites every
 * fragment of it takes the texture coordinates of its vertex, so the
 * square shows the one sample there (the derivatives are zero: the
 * magnification filter at the base level); with GL_POINT_SPRITE on and
 * GL_COORD_REPLACE set on the unit, s runs from 0 to 1 left to right
 * across the square and t from 0 to 1 down (GL_UPPER_LEFT, the default
 * GL_POINT_SPRITE_COORD_ORIGIN) or up (GL_LOWER_LEFT), and point
 * antialiasing is ignored. Either way the point becomes a textured square
 * in the scene: the four corners of the square interp_add_point computed
 * for it (its size with the distance attenuation of glPointParameter,
 * GL's pixels of an aliased point, a sprite's own square), in eye
 * space, with the texture and environment of the draw, unlit (a lit
 * point's colour is GL's, taken at its vertex). A smooth textured point
 * without sprites (a textured disc) and textured lines stay untextured,
 * with a note.
 */
#include "interp_internal.h"

#include "talloc.h"

struct interp_sprite {
    float p[3], right[3], up[3], color[4], uv[2];
    bool replace; /* GL_COORD_REPLACE: the corners take 0..1 */
};

void interp_sprites_free(interp *ip)
{
    tr_free(ip->sprites);
    ip->sprites = NULL;
    ip->nsprites = ip->cap_sprites = 0;
}

bool interp_point_textured(interp *ip, const scene_point *pt, const scene_vertex *v, bool smooth)
{
    if (ip->draw_unit[0] < 0)
        return false;
    interp_tex_unit u = interp_unit(ip, (uint32_t)ip->draw_unit[0]);
    bool sprite = ip->st.a.caps[INTERP_CAP_POINT_SPRITE];
    if (smooth && !sprite) {
        interp_note(ip, DIAG_NOTE_POINT_TEXTURE);
        return false;
    }
    if (tr_grow((void **)&ip->sprites, &ip->cap_sprites, ip->nsprites + 1, sizeof *ip->sprites) != 0) {
        if (ip->scene)
            ip->scene->failed = true;
        return false;
    }
    /* A sprite is the square (smoothing is ignored): the same extents. */
    struct interp_sprite *q = &ip->sprites[ip->nsprites++];
    memcpy(q->p, pt->p, sizeof q->p);
    memcpy(q->right, pt->right, sizeof q->right);
    memcpy(q->up, pt->up, sizeof q->up);
    memcpy(q->color, pt->color, sizeof q->color);
    memcpy(q->uv, v->tex, sizeof q->uv);
    q->replace = sprite && u.texture->coord_replace;
    return true;
}

void interp_point_sprites_end(interp *ip)
{
    scene *s = ip->scene;
    size_t n = ip->nsprites;
    ip->nsprites = 0;
    if (!s || n == 0)
        return;
    bool from1 = ip->prim_tex_from1;
    scene_look look = interp_current_look(ip);
    ip->prim_tex_from1 = from1;
    look.lit = 0;
    look.material = -1;
    look.flat = 0;
    if (look.texture < 0) { /* incomplete: GL draws the points untextured */
        for (size_t i = 0; i < n; i++) {
            scene_point *pt = scene_add_point(s);
            if (!pt)
                return;
            memset(pt, 0, sizeof *pt);
            memcpy(pt->p, ip->sprites[i].p, sizeof pt->p);
            memcpy(pt->right, ip->sprites[i].right, sizeof pt->right);
            memcpy(pt->up, ip->sprites[i].up, sizeof pt->up);
            memcpy(pt->color, ip->sprites[i].color, sizeof pt->color);
        }
        return;
    }
    mat4 id = mat4_identity();
    bool upper = ip->st.a.point.sprite_origin != GL_LOWER_LEFT;
    for (size_t i = 0; i < n; i++) {
        const struct interp_sprite *q = &ip->sprites[i];
        for (int k = 0; k < 4; k++)
            if (!interp_budget_vertex(ip))
                return;
        scene_vertex *v = scene_reserve_vertices(s, 4);
        if (!v)
            return;
        static const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        for (int c = 0; c < 4; c++) {
            memset(&v[c], 0, sizeof v[c]);
            for (int k = 0; k < 3; k++)
                v[c].pos[k] = q->p[k] + (float)sx[c] * q->right[k] + (float)sy[c] * q->up[k];
            v[c].normal[2] = 1;
            memcpy(v[c].color, q->color, sizeof v[c].color);
            if (q->replace) {
                v[c].tex[0] = (float)(sx[c] + 1) / 2;
                v[c].tex[1] = upper ? (float)(1 - sy[c]) / 2 : (float)(sy[c] + 1) / 2;
            } else {
                memcpy(v[c].tex, q->uv, sizeof v[c].tex);
            }
        }
        uint32_t b = (uint32_t)s->nverts;
        scene_commit_vertices(s, 4);
        if (!scene_mesh_for(s, &id, true, &look) || !scene_add_tri(s, b, b + 1, b + 2, b + 2) ||
            !scene_add_tri(s, b, b + 2, b + 3, b + 3))
            return;
    }
}

void interp_lines_textured(interp *ip)
{
    if (ip->draw_unit[0] < 0 || !ip->scene || interp_note_said(ip, DIAG_NOTE_TEX_LINES))
        return;
    bool from1 = ip->prim_tex_from1;
    scene_look look = interp_current_look(ip);
    ip->prim_tex_from1 = from1;
    if (look.texture >= 0)
        interp_note(ip, DIAG_NOTE_TEX_LINES);
}
