/*
 * touch.c: where two edges meet, for the checks that find it (sweep.c,
 * curve.c) and those that read it (valid.c): the list of the points where
 * two rings touch, and the message that ends the run where two edges cross,
 * overlap or touch where they must not.
 */
#include <stdio.h>
#include <stdlib.h>

#include "qtree.h"
#include "polyread.h"

static struct touch *touches;
static size_t ntouches, touchcap;

void
addtouch(long a, long b, struct point p)
{
	if (ntouches == touchcap) {
		touchcap = touchcap ? 2 * touchcap : 64;
		touches = xreallocarray(touches, touchcap, sizeof(*touches));
	}
	touches[ntouches].ring[0] = a < b ? a : b;
	touches[ntouches].ring[1] = a < b ? b : a;
	touches[ntouches++].p = p;
}

/* The touches recorded, for the caller to free; the list starts anew. */
struct touch *
taketouches(size_t *n)
{
	struct touch *t = touches;

	*n = ntouches;
	touches = NULL;
	ntouches = touchcap = 0;
	return t;
}

/* Which rings they are, as people count them: from 1 in input order. */
long
ringno(const struct input *in, const struct inring *r)
{
	return (long)(r - in->rings) + 1;
}

void
pairfail(const struct input *in, size_t ring1, size_t i, size_t ring2,
    size_t j, const char *what, struct point p)
{
	const struct inring *r = &in->rings[ring1], *q = &in->rings[ring2];
	char px[32], py[32];

	fmtreal(px, p.x);
	fmtreal(py, p.y);
	errat(r->file, r->line[i], "ring %ld edge %zu (line %ld) %s ring %ld "
	    "edge %zu (line %ld) at %s %s", ringno(in, r), i + 1, r->line[i],
	    what, ringno(in, q), j + 1, q->line[j], px, py);
}
