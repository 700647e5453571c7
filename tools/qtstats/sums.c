/*
 * sums.c: -s, the exact sums behind the figures of one shard, for -m
 * (merge.c) to add up: the head (the polygon's marks, and the region's
 * sums in the shard of the tree's root alone), the first cell, the nodes
 * with no cell below them, and the cells' counts and sums level by level.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

struct sums sums;

/* -s: a ring kept until the first cell says whether to sum it. */
void
keepring(const struct ring *g)
{
	struct ring *k;

	sums.rings = xgrow(sums.rings, &sums.ringcap, sums.nrings + 1,
	    sizeof(*sums.rings));
	k = &sums.rings[sums.nrings++];
	*k = *g;
	k->v = xreallocarray(NULL, g->n, sizeof(*k->v));
	memcpy(k->v, g->v, g->n * sizeof(*k->v));
	if (g->narcs > 0) {
		k->arc = xmalloc(g->n);
		memcpy(k->arc, g->arc, g->n);
		k->mid = xreallocarray(NULL, g->n, sizeof(*k->mid));
		memcpy(k->mid, g->mid, g->n * sizeof(*k->mid));
	}
}

/*
 * -s: at the first cell (NULL: none), the kept rings are summed whole
 * when it is the universe's root, else only counted.
 */
static void
decide(const struct cell *c)
{
	size_t i;

	sums.decided = 1;
	sums.moments = c == NULL || c->level == 0;
	if (sums.moments) {
		poly.perim = poly.perimlow = 0;
		for (i = 0; i < sums.nrings; i++)
			ring(&sums.rings[i]);
	} else
		for (i = 0; i < sums.nrings; i++) {
			poly.nrings++;
			poly.nholes += sums.rings[i].hole;
		}
	for (i = 0; i < sums.nrings; i++) {
		free(sums.rings[i].v);
		if (sums.rings[i].narcs > 0) {
			free(sums.rings[i].arc);
			free(sums.rings[i].mid);
		}
	}
	free(sums.rings);
	sums.nrings = 0;
}

static void
nodeat(struct nodeat *n, const struct cell *c)
{
	memcpy(n->path, c->path, c->level);
	n->path[c->level] = '\0';
	n->level = c->level;
	n->ix = c->ix;
	n->iy = c->iy;
	n->class = c->class == 0 ? 'N' : c->class;
}

/* Whether cell c lies in the subtree of the last root. */
static int
inroot(const struct cell *c)
{
	const struct nodeat *r = &sums.roots[sums.nroots - 1];

	return c->level > r->level && (r->level == 0 ||
	    cell_pathprefix(c->path, c->level, r->path, r->level) ==
	    r->level);
}

/*
 * The roots: the first cell, and each node after it outside the last
 * root's subtree (several shards' subtrees one after another, as
 * qtsplit -r writes them when given several roots).  The last node
 * dangles when cell c (NULL: none) is not inside it.
 */
void
sumcell(const struct cell *c)
{
	struct nodeat *o = &sums.open;

	if (sums.haveopen && (c == NULL || c->level <= o->level ||
	    (o->level > 0 &&
	    cell_pathprefix(c->path, c->level, o->path, o->level) < o->level))) {
		sums.dangling = xgrow(sums.dangling, &sums.cap,
		    sums.ndangling + 1, sizeof(*sums.dangling));
		sums.dangling[sums.ndangling++] = *o;
	}
	sums.haveopen = 0;
	if (!sums.decided)
		decide(c);
	if (c == NULL)
		return;
	if (sums.nroots == 0 || (c->class == 0 && !inroot(c))) {
		sums.roots = xgrow(sums.roots, &sums.rootcap, sums.nroots + 1,
		    sizeof(*sums.roots));
		nodeat(&sums.roots[sums.nroots++], c);
	}
	if (c->class == 0) {
		nodeat(o, c);
		sums.haveopen = 1;
	}
}

/*
 * -s: the sums behind the figures, exact, as lines that -m reads: the
 * head's (the same in every shard), the first cell and the nodes with no
 * cell below them, and per level the counts and the sums of 2 IX + 1 and
 * 2 IY + 1 (128 bits: high and low 64), the expansions as their
 * components, each written so that it reads back to the same double.
 */
static void
put128(const struct u128 *v)
{
	printf(" %llu %llu", (unsigned long long)v->hi,
	    (unsigned long long)v->lo);
}

static void
putxsum(const char *key, const struct xsum *x)
{
	char buf[32];
	int i;

	fputs(key, stdout);
	for (i = 0; i < x->n; i++)
		printf(" %s", (fmtreal(buf, x->h[i]), buf));
	putchar('\n');
}

static void
putnodeat(const char *key, const struct nodeat *n, int withclass)
{
	printf("%s %s %d %llu %llu", key, n->level > 0 ? n->path : ".",
	    n->level, (unsigned long long)n->ix, (unsigned long long)n->iy);
	if (withclass)
		printf(" %c", n->class);
	putchar('\n');
}

void
sumsreport(const char *name)
{
	char b0[32], b1[32], b2[32];
	size_t i;
	int l, k;

	if (mesh.present)
		errat(name, 0, "a mesh: -s sums the figures of trees only");
	sumcell(NULL);
	printf("qtstats-sums 1\n");
	if (tree.haveuniverse)
		printf("universe %s %s %s\n", (fmtreal(b0, tree.u.x0), b0),
		    (fmtreal(b1, tree.u.y0), b1),
		    (fmtreal(b2, tree.u.size), b2));
	printf("objects %ld\nrings %llu\nholes %llu\n", poly.nobjects,
	    poly.nrings, poly.nholes);
	printf("perimeter %s %s\n", (fmtreal(b0, poly.perim), b0),
	    (fmtreal(b1, poly.perimlow), b1));
	if (sums.moments) {
		putxsum("area2", &poly.region.a2);
		putxsum("moment_x", &poly.region.mx);
		putxsum("moment_y", &poly.region.my);
	}
	for (i = 0; i < sums.nroots; i++)
		putnodeat("root", &sums.roots[i], 1);
	for (i = 0; i < sums.ndangling; i++)
		putnodeat("dangling", &sums.dangling[i], 0);
	for (l = 0; l <= tree.deepest; l++) {
		const struct levelstat *s = &tree.lev[l];

		printf("level %d %llu %llu %llu %llu", l, s->nodes,
		    s->leaves[F], s->leaves[E], s->leaves[P]);
		put128(&s->nodesx);
		put128(&s->nodesy);
		for (k = 0; k < 3; k++) {
			put128(&s->sx[k]);
			put128(&s->sy[k]);
		}
		putchar('\n');
	}
	printf("cut %llu", tree.ncut);
	putxsum("", &tree.cut);
	printf("end\n");
}
