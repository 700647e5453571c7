/*
 * quality.c: an element's smallest angle, and the bin of -q's colour
 * scale that it falls in.  The scale is in the degrees of a triangle, whose
 * best in a quadtree's mesh is the right isosceles one, half a square, of
 * 45 degrees; an element of n > 3 vertices has its angle scaled by 45 over
 * that of the regular n-gon, so that a square's 90 degrees count as 45.
 */
#include <math.h>

#include "qtree.h"
#include "qt2svg.h"

/* ColorBrewer's RdYlGn of seven classes: red is poor, green good. */
const char *anglecolour[NQBIN] = { "#D73027", "#FC8D59", "#FEE08B",
    "#FFFFBF", "#D9EF8B", "#91CF60", "#1A9850" };
/* The bins' bounds, in a triangle's degrees. */
const int anglebound[NQBIN - 1] = { 20, 25, 30, 35, 40, 45 };

/*
 * The smallest interior angle, in degrees, of an element in world terms:
 * at each vertex, from the edge out to the edge in, turning the way the
 * element runs, so that a reflex vertex counts as more than 180 degrees.
 * A repeated vertex makes an angle of 0.
 */
double
smallestangle(const unsigned long long *e)
{
	const struct point *p, *q, *r;
	double area = 0, min = 360, s, ax, ay, bx, by, t;
	size_t i, n = e[0];

	if (n < 3)
		return 0;
	for (i = 0; i < n; i++) {
		p = &pic.verts[e[1 + i] - 1];
		q = &pic.verts[e[1 + (i + 1) % n] - 1];
		area += p->x * q->y - q->x * p->y;
	}
	s = area < 0 ? -1 : 1;
	for (i = 0; i < n; i++) {
		p = &pic.verts[e[1 + (i + n - 1) % n] - 1];
		q = &pic.verts[e[1 + i] - 1];
		r = &pic.verts[e[1 + (i + 1) % n] - 1];
		ax = p->x - q->x;
		ay = p->y - q->y;
		bx = r->x - q->x;
		by = r->y - q->y;
		t = atan2(s * (bx * ay - by * ax), ax * bx + ay * by);
		if (t < 0)
			t += 2 * acos(-1);
		if (t < min)
			min = t;
	}
	return min * 180 / acos(-1);
}

/*
 * The bin, 0 (poorest) to NQBIN - 1: below the first bound, between two,
 * or at the last or above.  An angle within 1e-9 degrees below a bound
 * counts as on it, so that rounding leaves a right isosceles triangle at
 * 45 degrees.
 */
int
anglebin(const unsigned long long *e)
{
	double t = smallestangle(e);
	size_t n = e[0];
	int b;

	if (n > 3)
		t *= 45 / (180.0 * (n - 2) / n);
	for (b = 0; b < NQBIN - 1 && t + 1e-9 >= anglebound[b]; b++)
		;
	return b;
}
