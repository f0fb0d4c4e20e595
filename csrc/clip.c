/*
** clip.c -- clipping against the view volume and user planes (ES 1.1 §2.11).
** Consumes: vertices with clip (and, for user planes, eye) coordinates.
** Produces: the clipped polygon or segment; new vertices carry every
**       attribute interpolated linearly in clip space.
**
** Determinism. A new vertex on an edge is interpolated from the edge's two
** endpoints taken in a canonical order (lexicographic on clip coordinates),
** not in the order the polygon happens to walk them. Two triangles sharing
** an edge, or one triangle clipped by a plane and by its negation, therefore
** produce bit-identical intersection points, which the invariance rules of
** Appendix A need (no cracks, complementary planes cover every pixel once).
** The w > eps guard plane keeps the perspective division defined.
*/
#include <string.h>
#include "clip.h"
#include "vertex.h"

static int before(const Vertex *a, const Vertex *b)
{
    for (int i = 0; i < 4; i++)
        if (a->clip[i] != b->clip[i])
            return a->clip[i] < b->clip[i];
    return 0;
}

static void lerp_vertex(Vertex *r, const Vertex *p, const Vertex *q, CLIPT t, int two_sided)
{
    for (int i = 0; i < 4; i++) {
        r->clip[i] = num_lerp(p->clip[i], q->clip[i], t);
        r->eye[i] = num_lerp(p->eye[i], q->eye[i], t);
        r->color[i] = frag_lerp_clip(p->color[i], q->color[i], t);
        /* back colours exist only with two-sided lighting */
        r->color_back[i] = two_sided ? frag_lerp_clip(p->color_back[i], q->color_back[i], t) : 0;
    }
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        for (int i = 0; i < 4; i++)
            r->tex[u][i] = num_lerp(p->tex[u][i], q->tex[u][i], t);
    r->point_size = num_lerp(p->point_size, q->point_size, t);
    r->fog = num_lerp(p->fog, q->fog, t);
    r->outcode = CLIP_NEW_VERTEX;
}

/* the point where edge (a, b) meets plane `bit`; a and b are on opposite sides */
static void intersect(const GlesContext *ctx, Vertex *r, const Vertex *a, const Vertex *b, unsigned int bit)
{
    if (before(b, a)) {
        const Vertex *t = a;
        a = b;
        b = t;
    }
    NUM da = vertex_plane_distance(ctx, a, bit);
    NUM db = vertex_plane_distance(ctx, b, bit);
    lerp_vertex(r, a, b, num_clip_t(da, db), ctx->two_sided);
}

int clip_polygon(const GlesContext *ctx, const Vertex *const *in, int n, unsigned int codes,
                 const Vertex **out, Vertex *scratch)
{
    const Vertex *buf[2][CLIP_MAX_VERTS];
    int used = 0;
    int cur = 0;
    memcpy(buf[0], in, (size_t)n * sizeof *in);
    for (unsigned int bit = 1; bit && codes; bit <<= 1) {
        if (!(codes & bit))
            continue;
        codes &= ~bit;
        const Vertex **src = buf[cur], **dst = buf[cur ^ 1];
        int m = 0;
        for (int i = 0; i < n; i++) {
            const Vertex *a = src[i], *b = src[(i + 1) % n];
            NUM da = vertex_plane_distance(ctx, a, bit);
            NUM db = vertex_plane_distance(ctx, b, bit);
            int ina = da >= 0, inb = db >= 0;
            if (ina)
                dst[m++] = a;
            if (ina != inb && m < CLIP_MAX_VERTS && used < 2 * CLIP_MAX_VERTS) {
                Vertex *r = &scratch[used++];
                intersect(ctx, r, a, b, bit);
                dst[m++] = r;
            }
        }
        n = m;
        cur ^= 1;
        if (n < 3)
            return 0;
    }
    memcpy(out, buf[cur], (size_t)n * sizeof *out);
    return n;
}

int clip_line(const GlesContext *ctx, const Vertex *a, const Vertex *b, unsigned int codes,
              const Vertex **pa, const Vertex **pb, Vertex *scratch)
{
    int used = 0;
    for (unsigned int bit = 1; bit && codes; bit <<= 1) {
        if (!(codes & bit))
            continue;
        codes &= ~bit;
        NUM da = vertex_plane_distance(ctx, a, bit);
        NUM db = vertex_plane_distance(ctx, b, bit);
        if (da < 0 && db < 0)
            return 0;
        if (da >= 0 && db >= 0)
            continue;
        Vertex *r = &scratch[used++];
        intersect(ctx, r, a, b, bit);
        if (da < 0)
            a = r;
        else
            b = r;
    }
    *pa = a;
    *pb = b;
    return 1;
}
