/*
 * solid.c: a 3D stream (qtree(5), Solids).  main.c hands it the stream at
 * its header.  With -z the picture is a slice: the cubes whose half-open
 * z range [z, z + size) holds the plane's z become the squares of a 2D
 * tree (a cube's children cut by the plane are its four of one layer, in
 * the quadrants' order, so the squares come in preorder), drawn as 2D
 * leaves are; the shells' sections become rings.  Without -z the leaves
 * go to iso.c's isometric view.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

/*
 * A piece of a section: where the plane crosses one triangle, from the
 * edge it enters by to the edge it leaves by, each edge named by its two
 * vertices (the lower number first), and the point on the first.
 */
struct piece {
	size_t		 from[2], to[2];
	struct point	 p;
	int		 used;
};

static struct universe3 u3;

/*
 * Which side of the plane a vertex is on: a vertex on it counts as below,
 * so that the section is the solid's at z + e, e > 0 infinitesimal, as
 * the squares are the cubes' that reach above z.
 */
static int
above(struct point3 v)
{
	return v.z > opt.z;
}

/* Where the plane meets the edge from a below to b above. */
static struct point
crossing(struct point3 a, struct point3 b)
{
	struct point p;
	double t = (opt.z - a.z) / (b.z - a.z);

	p.x = a.x + t * (b.x - a.x);
	p.y = a.y + t * (b.y - a.y);
	return p;
}

static int
edgecmp(const size_t *a, const size_t *b)
{
	if (a[0] != b[0])
		return a[0] < b[0] ? -1 : 1;
	return a[1] < b[1] ? -1 : a[1] > b[1];
}

static int
piececmp(const void *a, const void *b)
{
	return edgecmp(((const struct piece *)a)->from,
	    ((const struct piece *)b)->from);
}

static void
edgename(size_t e[2], size_t i, size_t j)
{
	e[0] = i < j ? i : j;
	e[1] = i < j ? j : i;
}

/*
 * The plane's piece of triangle t, if it crosses it.  Seen from outside,
 * a triangle runs counter-clockwise; its piece runs from the edge that
 * goes down through the plane to the edge that goes up, so that the
 * solid's side of the section lies to the piece's left, as an outer
 * ring's inside does in 2D.
 */
static int
cutpiece(const struct shell *g, size_t t, struct piece *pc)
{
	const size_t *v = g->t + 3 * t;
	int i, n = 0;

	for (i = 0; i < 3; i++) {
		size_t a = v[i], b = v[(i + 1) % 3];
		int sa = above(g->v[a]), sb = above(g->v[b]);

		if (sa && !sb) {
			edgename(pc->from, a, b);
			pc->p = crossing(g->v[b], g->v[a]);
			n++;
		} else if (!sa && sb) {
			edgename(pc->to, a, b);
			n++;
		}
	}
	pc->used = 0;
	return n == 2;
}

/* Twice a loop's signed area, counter-clockwise positive. */
static double
loopsign(const struct point *v, size_t n)
{
	double a = 0;
	size_t i;

	for (i = 0; i < n; i++) {
		const struct point *p = &v[i], *q = &v[(i + 1) % n];

		a += (p->x - v[0].x) * (q->y - v[0].y) -
		    (q->x - v[0].x) * (p->y - v[0].y);
	}
	return a;
}

/*
 * A shell's section, as rings.  Every edge that the plane crosses lies in
 * two triangles, which cross it in opposite directions, so it starts one
 * piece and ends another: the pieces, chained by their edges, make closed
 * loops.  A loop running clockwise bounds a hole in the section.
 */
static void
section(const struct shell *g)
{
	static long id;
	struct piece *pc = xcalloc(g->nt > 0 ? g->nt : 1, sizeof(*pc));
	struct point *loop = NULL;
	size_t n = 0, t, cap = 0;

	for (t = 0; t < g->nt; t++)
		n += cutpiece(g, t, &pc[n]);
	qsort(pc, n, sizeof(*pc), piececmp);
	for (t = 0; t < n; t++) {
		struct piece *q = &pc[t], key;
		struct ring r;
		size_t len = 0;

		while (q != NULL && !q->used) {
			q->used = 1;
			loop = xgrow(loop, &cap, len + 1, sizeof(*loop));
			loop[len++] = q->p;
			memcpy(key.from, q->to, sizeof(key.from));
			q = bsearch(&key, pc, n, sizeof(*pc), piececmp);
		}
		if (len < 3)
			continue;
		memset(&r, 0, sizeof(r));
		r.id = ++id;
		r.n = len;
		r.v = loop;
		r.hole = loopsign(loop, len) < 0;
		ring(&r);
	}
	free(loop);
	free(pc);
}

/* A cube that the plane cuts, as the square it cuts out. */
static void
slicecell(const struct cell3 *c)
{
	struct cell s;

	if (!(c->z <= opt.z && opt.z < cell_coord(u3.z0, u3.size, c->level,
	    c->iz + 1)))
		return;
	memset(&s, 0, sizeof(s));
	s.path = c->path;
	s.level = c->level;
	s.ix = c->ix;
	s.iy = c->iy;
	s.x = c->x;
	s.y = c->y;
	s.size = c->size;
	s.class = c->class;
	s.frac = -1;
	seecell(&s);
	if (s.class != 0)
		leaf(&s);
}

static void
setuniverse(const struct universe3 *u)
{
	char z0[32], z1[32], z[32];

	u3 = *u;
	pic.u.x0 = u->x0;
	pic.u.y0 = u->y0;
	pic.u.size = u->size;
	if (!opt.zflag) {
		if (opt.bflag)
			die(2, "-b: a 3D stream's window is a slice's: -b needs "
			    "-z");
		return;
	}
	if (!(u->z0 <= opt.z && opt.z < u->z0 + u->size)) {
		fmtreal(z0, u->z0);
		fmtreal(z1, u->z0 + u->size);
		fmtreal(z, opt.z);
		die(2, "-z %s: outside the universe's z range [%s, %s)", z, z0,
		    z1);
	}
	if (opt.bflag)
		rectwindow();
}

int
solidmain(struct qtreader *r)
{
	struct qt3reader *s = qt3_open(r);
	struct qt3rec rec;

	while (qt3_read(s, &rec) != QT_EOF)
		switch (rec.kind) {
		case QT_UNIVERSE:
			setuniverse(&rec.u);
			break;
		case QT_LEVEL:
			pic.level = rec.level;
			break;
		case QT_SHELL:
			if (opt.zflag)
				section(&rec.shell);
			break;
		case QT_NODE:
		case QT_LEAF:
			if (opt.zflag)
				slicecell(&rec.c);
			else
				isocell(&rec.c);
			break;
		default:
			break;
		}
	qt3_close(s);
	qt_close(r);
	if (opt.zflag)
		writesvg();
	else
		isodraw(u3.z0);
	closeout();
	return 0;
}
