/* interp_bounds.c: the frame's budget, and what damage left out of it.
 *
 * Budget. A trace can ask for far more work than its size: a display list
 * that calls itself twice runs 2^20 bodies before the call cap stops it,
 * each drawing what its body draws. So every frame has a budget
 * (INTERP_BUDGET_* in interp.h, docs/mapping.md "Bounds") of commands run,
 * vertices assembled, vertices and primitives the scene holds, instances
 * and texture bytes. The run loop checks it after every command, vertex
 * assembly and texture reads before they happen; the first check that
 * fails cuts the frame: every later command of the frame, in any list, is
 * skipped, and interp_frame_cut says where and why. The scene keeps what
 * came before, so the writer still writes a valid (if incomplete) scene.
 *
 * Missing parts. A display-list body or texture image that the trace
 * cannot supply (a checksum mismatch, a chunk lost in a damaged region) is
 * left out of the frame with a diagnostic; here the frame also remembers
 * it, so that the CLI can say which frames were written without what, and
 * exit with 1, whether or not diagnostics are printed.
 */
#include "interp_internal.h"

#include <stdio.h>
#include <string.h>

void interp_bounds_begin_frame(interp *ip)
{
    ip->cmds_run = ip->assembled = ip->texels = 0;
    memset(&ip->peak, 0, sizeof ip->peak);
    ip->cut = false;
    ip->heavy = false;
    ip->cut_why[0] = '\0';
    ip->nmissing = 0;
    ip->missing[0] = '\0';
}

static bool cut(interp *ip, uint64_t offset, const char *what, unsigned long long limit)
{
    ip->cut = true;
    snprintf(ip->cut_why, sizeof ip->cut_why,
             "cut at @0x%llx%s: over the frame budget of %llu %s; the rest of the frame is "
             "not translated",
             (unsigned long long)offset, ip->list_depth ? " (in a display list)" : "", limit,
             what);
    return true;
}

bool interp_budget_over(interp *ip, uint64_t offset)
{
    if (ip->cut)
        return true;
    const scene *s = ip->scene;
    if (ip->cmds_run > INTERP_LIMIT(ip, COMMANDS))
        return cut(ip, offset, "commands run", INTERP_LIMIT(ip, COMMANDS));
    if (!s)
        return false;
    if (s->nverts > INTERP_LIMIT(ip, VERTICES))
        return cut(ip, offset, "vertices", INTERP_LIMIT(ip, VERTICES));
    if (s->ntris > INTERP_LIMIT(ip, TRIANGLES))
        return cut(ip, offset, "triangles", INTERP_LIMIT(ip, TRIANGLES));
    if (s->nlines + s->npoints > INTERP_LIMIT(ip, LINES))
        return cut(ip, offset, "lines and points", INTERP_LIMIT(ip, LINES));
    if (s->nsolids > INTERP_LIMIT(ip, SOLIDS))
        return cut(ip, offset, "solids", INTERP_LIMIT(ip, SOLIDS));
    if (s->ninstances > INTERP_LIMIT(ip, INSTANCES))
        return cut(ip, offset, "display-list instances", INTERP_LIMIT(ip, INSTANCES));
    return false;
}

void interp_set_budget_shift(interp *ip, unsigned shift)
{
    ip->budget_shift = shift < 16 ? shift : 16;
}

void interp_set_heavy(interp *ip, interp_heavy_fn fn, void *ctx)
{
    ip->heavy_fn = fn;
    ip->heavy_ctx = ctx;
}

/* What the scene holds, with what the writer makes of it: lines and
 * points become a solid each (measured: about 380 bytes a line in all). */
void interp_heavy_check(interp *ip)
{
    const scene *s = ip->scene;
    if (!s)
        return;
    uint64_t bytes = (uint64_t)s->cap_verts * sizeof *s->verts +
                     (uint64_t)s->cap_tris * sizeof *s->tris * 2 +
                     (uint64_t)(s->cap_lines + s->cap_points) * 400 +
                     (uint64_t)s->cap_solids * sizeof *s->solids * 2 +
                     (uint64_t)s->cap_instances * sizeof *s->instances + ip->texels;
    if (bytes > INTERP_HEAVY_BYTES) {
        ip->heavy = true;
        ip->heavy_fn(ip->heavy_ctx);
    }
}

/* The command being run, for a cut inside one (an array draw, a texture). */
static uint64_t here(const interp *ip) { return ip->cmd ? ip->cmd->offset : 0; }

bool interp_budget_vertex(interp *ip)
{
    if (ip->cut)
        return false;
    if (++ip->assembled > INTERP_LIMIT(ip, ASSEMBLED)) {
        cut(ip, here(ip), "vertices assembled", INTERP_LIMIT(ip, ASSEMBLED));
        return false;
    }
    if (ip->scene && ip->scene->nverts >= INTERP_LIMIT(ip, VERTICES)) {
        cut(ip, here(ip), "vertices", INTERP_LIMIT(ip, VERTICES));
        return false;
    }
    return true;
}

bool interp_budget_texels(interp *ip, uint64_t bytes)
{
    if (ip->cut)
        return false;
    if (bytes > INTERP_LIMIT(ip, TEXELS) - ip->texels) {
        cut(ip, here(ip), "texture bytes", INTERP_LIMIT(ip, TEXELS));
        return false;
    }
    ip->texels += bytes;
    return true;
}

const char *interp_frame_cut(const interp *ip) { return ip->cut ? ip->cut_why : NULL; }

static void peak(uint64_t *p, uint64_t n)
{
    if (n > *p)
        *p = n;
}

void interp_budget_peak(interp *ip)
{
    const scene *s = ip->scene;
    if (!s)
        return;
    peak(&ip->peak.vertices, s->nverts);
    peak(&ip->peak.triangles, s->ntris);
    peak(&ip->peak.lines, (uint64_t)s->nlines + s->npoints);
    peak(&ip->peak.solids, s->nsolids);
    peak(&ip->peak.instances, s->ninstances);
}

void interp_budget_used(const interp *ip, interp_budget_use *used, interp_budget_use *limit)
{
    *used = ip->peak;
    const scene *s = ip->scene;
    if (s) { /* as they stand, mid-frame */
        peak(&used->vertices, s->nverts);
        peak(&used->triangles, s->ntris);
        peak(&used->lines, (uint64_t)s->nlines + s->npoints);
        peak(&used->solids, s->nsolids);
        peak(&used->instances, s->ninstances);
    }
    used->commands = ip->cmds_run;
    used->assembled = ip->assembled;
    used->texels = ip->texels;
    *limit = (interp_budget_use){INTERP_LIMIT(ip, COMMANDS),  INTERP_LIMIT(ip, ASSEMBLED),
                                 INTERP_LIMIT(ip, VERTICES),  INTERP_LIMIT(ip, TRIANGLES),
                                 INTERP_LIMIT(ip, LINES),     INTERP_LIMIT(ip, SOLIDS),
                                 INTERP_LIMIT(ip, INSTANCES), INTERP_LIMIT(ip, TEXELS)};
}

void interp_missing(interp *ip, const char *what)
{
    /* The same part again (a list called twice, a texture drawn twice) is
     * not another part: the first INTERP_MISSING_KEPT are told apart. */
    uint64_t h = 0xcbf29ce484222325ull;
    for (const char *p = what; *p; p++)
        h = (h ^ (unsigned char)*p) * 0x100000001b3ull;
    uint32_t kept = ip->nmissing < INTERP_MISSING_KEPT ? ip->nmissing : INTERP_MISSING_KEPT;
    for (uint32_t k = 0; k < kept; k++)
        if (ip->missing_hash[k] == h)
            return;
    if (ip->nmissing < INTERP_MISSING_KEPT)
        ip->missing_hash[ip->nmissing] = h;
    if (ip->nmissing == 0)
        snprintf(ip->missing, sizeof ip->missing, "%s", what);
    ip->nmissing++;
}

const char *interp_frame_missing(const interp *ip, uint32_t *count)
{
    *count = ip->nmissing;
    return ip->nmissing ? ip->missing : NULL;
}
