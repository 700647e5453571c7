/*
 * rings.c: the polygon's rings, kept in world terms as they come and drawn
 * over the leaves, outer rings and holes apart, an object's in a colour of
 * its own.  Long rings are cut into path elements of RINGCHUNK vertices;
 * vertices that add nothing inside the clip box are left out, so that a
 * ring far finer than a pixel costs the picture little.
 */
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

/* Ring styles, which the legend repeats. */
const char ringstyle[] = "stroke=\"#000000\" stroke-width=\"1.5\"";
const char holestyle[] = "stroke-dasharray=\"5 3\"";
/*
 * The rings of a combined stream's objects (qtbool), a stroke colour an
 * object, in turn: black, then Okabe and Ito's vermillion, bluish green
 * and reddish purple.
 */
static const char *objectcolour[] = { "#000000", "#D55E00", "#009E73",
    "#CC79A7" };

/* A ring record, kept in world terms with its arcs' radii and flags. */
void
ring(const struct ring *g)
{
	struct ringrec *r;

	pic.rv = xgrow(pic.rv, &pic.rvcap, pic.nrv + g->n, sizeof(*pic.rv));
	memcpy(pic.rv + pic.nrv, g->v, g->n * sizeof(*g->v));
	pic.rings = xgrow(pic.rings, &pic.ringcap, pic.nrings + 1,
	    sizeof(*pic.rings));
	r = &pic.rings[pic.nrings++];
	r->first = pic.nrv;
	r->n = g->n;
	r->hole = g->hole;
	r->arcs = g->narcs > 0;
	if (r->arcs) {
		size_t i;

		pic.ra = xgrow(pic.ra, &pic.racap, pic.nrv + g->n,
		    sizeof(*pic.ra));
		for (i = 0; i < g->n; i++) {
			struct ringarc *ra = &pic.ra[pic.nrv + i];
			struct arc c;
			struct arcmeasures m;

			ra->r = 0;
			if (!g->arc[i] || arc_init(&c, g->v[i], g->mid[i],
			    g->v[(i + 1) % g->n]) < 0)
				continue;
			arc_measures(&c, &m);
			ra->r = m.r;
			/*
			 * The arc runs counter-clockwise when m lies right of
			 * the chord, and SVG's sweep 1 is clockwise as seen.
			 */
			ra->large = c.oc == c.sd;
			ra->sweep = c.sd > 0;
		}
	}
	r->object = pic.object;
	pic.nrv += g->n;
	pic.nring[pic.object][g->hole != 0]++;
}

/*
 * The rings of one kind.  A ring is an open polyline back to its first
 * vertex, so that a long one can go on in the next path element from
 * where the last one stopped.
 */
struct ringpath {
	const char	*head;
	int		 open;
	size_t		 n;		/* vertices in the path element */
	long long	 lastx, lasty;
	int		 arc;		/* the last command was an A */
};

/* move: 1 M, 0 a line, -1 nothing (an arc's start: the path opened). */
static void
ringvertex(struct ringpath *rp, long long x, long long y, int move)
{
	if (!rp->open) {
		outs(rp->head);
		outs("<path d=\"");
		rp->open = 1;
		rp->n = 0;
	} else if (rp->n >= RINGCHUNK) {
		outs("\"/>\n<path d=\"");
		rp->n = 0;
		if (move <= 0) {
			out("M", 1);
			outxy(rp->lastx, rp->lasty);
			rp->n = 1;
		}
	}
	rp->n++;
	if (move < 0)
		return;
	out(move ? "M" : rp->arc ? " L" : " ", move || !rp->arc ? 1 : 2);
	rp->arc = 0;
	outxy(x, y);
	rp->lastx = x;
	rp->lasty = y;
}

/* An arc to (x, y), SVG's A command: rx ry rotation large sweep x y. */
static void
ringarcto(struct ringpath *rp, const struct ringarc *ra, long long x,
    long long y)
{
	long long r = hund(ra->r * pic.win.scale);
	char flags[16];

	ringvertex(rp, rp->lastx, rp->lasty, -1);
	snprintf(flags, sizeof(flags), " 0 %d %d ", ra->large, ra->sweep);
	out(" A", 2);
	outxy(r, r);
	outs(flags);
	outxy(x, y);
	rp->lastx = x;
	rp->lasty = y;
	rp->arc = 1;
}

/*
 * A vertex that lands where the last one drawn did is left out, and so is
 * one that lies, with the last drawn and the next, beyond one side of the
 * clip box: the line that replaces its two lies there too.  An arc's end
 * is always drawn, by an A command.
 */
static void
drawring(struct ringpath *rp, const struct ringrec *r)
{
	const struct point *v = pic.rv + r->first;
	const struct ringarc *ra = r->arcs ? pic.ra + r->first : NULL;
	long long x0 = pixelx(v[0].x), y0 = pixely(v[0].y), x, y, nx, ny;
	int last, code, ncode;
	size_t i;

	ringvertex(rp, x0, y0, 1);
	last = outcode(x0, y0);
	x = pixelx(v[1 % r->n].x);
	y = pixely(v[1 % r->n].y);
	code = outcode(x, y);
	for (i = 1; i < r->n; i++) {
		if (i + 1 < r->n) {
			nx = pixelx(v[i + 1].x);
			ny = pixely(v[i + 1].y);
		} else {
			nx = x0;
			ny = y0;
		}
		ncode = outcode(nx, ny);
		if (ra != NULL && ra[i - 1].r > 0) {
			ringarcto(rp, &ra[i - 1], x, y);
			last = code;
		} else if ((x != rp->lastx || y != rp->lasty) &&
		    ((last & code & ncode) == 0 ||
		    (ra != NULL && ra[i].r > 0))) {
			ringvertex(rp, x, y, 0);
			last = code;
		}
		x = nx;
		y = ny;
		code = ncode;
	}
	if (ra != NULL && ra[r->n - 1].r > 0)
		ringarcto(rp, &ra[r->n - 1], x0, y0);
	else
		ringvertex(rp, x0, y0, 0);
}

/* The style of object k's rings: the black one for k = 0, no object. */
const char *
objectstyle(char *buf, size_t size, long k)
{
	if (k == 0)
		return ringstyle;
	snprintf(buf, size, "stroke=\"%s\" stroke-width=\"1.5\"",
	    objectcolour[(k - 1) % (sizeof(objectcolour) /
	    sizeof(objectcolour[0]))]);
	return buf;
}

/* The outer rings, then the holes, of object k (0: of a polygon). */
static void
objectrings(long k)
{
	char head[2][256], style[64], id[32];
	struct ringpath rp[2] = { { 0 }, { 0 } };
	size_t i;
	int h;

	id[0] = '\0';
	if (k > 0)
		snprintf(id, sizeof(id), "object-%ld-", k);
	snprintf(head[0], sizeof(head[0]), "<g id=\"%souter-rings\" "
	    "fill=\"none\" %s stroke-linejoin=\"round\" "
	    "clip-path=\"url(#map)\">\n", id, objectstyle(style,
	    sizeof(style), k));
	snprintf(head[1], sizeof(head[1]), "<g id=\"%sholes\" fill=\"none\" "
	    "%s %s stroke-linejoin=\"round\" clip-path=\"url(#map)\">\n",
	    id, objectstyle(style, sizeof(style), k), holestyle);
	for (h = 0; h < 2; h++) {
		rp[h].head = head[h];
		for (i = 0; i < pic.nrings; i++)
			if ((pic.rings[i].hole != 0) == h &&
			    pic.rings[i].object == k)
				drawring(&rp[h], &pic.rings[i]);
		if (rp[h].open)
			outs("\"/>\n</g>\n");
	}
}

void
rings(void)
{
	long k;

	for (k = 0; k <= pic.object; k++)
		objectrings(k);
}
