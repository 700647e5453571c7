/*
 * poly.c: the polygon, its rings summed as they stream past: area and
 * moments exactly (expansions, lib/area.c), the perimeter as a
 * compensated sum, arcs by their chords and circular segments.  With -s
 * the rings wait in sums.c until the first cell says whether the shard
 * carries the region's sums; their perimeter is summed at once.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

struct polygon poly;

static void
addperim(double len)
{
	double t = poly.perim + len;

	/* Neumaier: keep what the larger addend rounds away */
	if (fabs(poly.perim) >= fabs(len))
		poly.perimlow += (poly.perim - t) + len;
	else
		poly.perimlow += (len - t) + poly.perim;
	poly.perim = t;
}

static void
edge(struct point a, struct point b)
{
	area_moedge(&poly.ring, a, b);
	addperim(hypot(b.x - a.x, b.y - a.y));
}

/*
 * A ring adds its area and moments with the sign its kind gives it,
 * outer +, hole -, whatever way it runs.
 */
static void
endring(int hole)
{
	int want = hole ? -1 : 1, sign;

	sign = area_sign(&poly.ring.a2);
	area_moadd(&poly.region, &poly.ring, sign == want || sign == 0 ? 1 : -1);
	area_mozero(&poly.ring);
}

/*
 * An arc adds its chord's exact terms and its circular segment's, the
 * latter in floating point: the segment counts positive when the loop
 * along the arc and back along the chord runs counter-clockwise, which is
 * when m lies right of a->b.
 */
static void
arcedge(struct point a, struct point m, struct point b)
{
	struct arc c;
	struct arcmeasures g;
	double s;

	if (arc_init(&c, a, m, b) < 0)
		die(1, "arc through three points on a line");	/* read.c */
	arc_measures(&c, &g);
	s = -c.sd * g.area;
	area_moedge(&poly.ring, a, b);
	area_add(&poly.ring.a2, 2 * s);
	area_add(&poly.ring.mx, 6 * s * g.gx);
	area_add(&poly.ring.my, 6 * s * g.gy);
	addperim(g.len);
}

/* The perimeter alone, as ring() sums it. */
static void
ringperim(const struct ring *g)
{
	struct arc c;
	struct arcmeasures m;
	size_t i;

	for (i = 0; i < g->n; i++) {
		struct point a = g->v[i], b = g->v[(i + 1) % g->n];

		if (g->narcs > 0 && g->arc[i]) {
			if (arc_init(&c, a, g->mid[i], b) < 0)
				die(1, "arc through three points on a line");
			arc_measures(&c, &m);
			addperim(m.len);
		} else
			addperim(hypot(b.x - a.x, b.y - a.y));
	}
}

void
ring(const struct ring *g)
{
	size_t i;

	if (sums.on && !sums.decided) {
		keepring(g);
		ringperim(g);
		return;
	}
	poly.nrings++;
	poly.nholes += g->hole;
	for (i = 0; i < g->n; i++)
		if (g->narcs > 0 && g->arc[i])
			arcedge(g->v[i], g->mid[i], g->v[(i + 1) % g->n]);
		else
			edge(g->v[i], g->v[(i + 1) % g->n]);
	endring(g->hole);
}

/* |approximation - polygon| / polygon, the difference taken exactly. */
double
relerr(const struct xsum *approx, double area)
{
	struct xsum d;
	double v;

	area_init(&d);
	area_addsum(&d, approx, 1);
	area_addsum(&d, &poly.region.a2, -0.5);
	v = fabs(area_round(&d)) / area;
	area_free(&d);
	return v;
}

/*
 * Returns the polygon's area, 0 without rings.  The rings of a combined
 * stream bound several objects, and its region is theirs combined, which
 * the rings alone do not give: the figures of the region are left out.
 */
double
polygonfigures(void)
{
	double area = 0, cx, cy;

	if (poly.nobjects > 0)
		putcount("objects", poly.nobjects);
	putcount("rings", poly.nrings);
	putcount("holes", poly.nholes);
	if (poly.nobjects > 0) {
		printf("# left out, the rings bound %ld objects combined: "
		    "polygon_area perimeter centroid_x centroid_y "
		    "area_full_relerr area_full_partial_relerr\n",
		    poly.nobjects);
		return 0;
	}
	if (poly.nrings > 0) {
		area_moresult(&poly.region, &area, &cx, &cy);
		putreal("polygon_area", area);
		putreal("perimeter", poly.perim + poly.perimlow);
		putreal("centroid_x", cx);
		putreal("centroid_y", cy);
	}
	return area;
}
