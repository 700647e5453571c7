/*
 * solid.c: qtstats on a 3D stream: the solid's figures from its shells,
 * the octree's from its cells, as key value lines (qtstats(1), Solids).
 * main.c hands it the stream at its first record, and its lines go out
 * through main.c's putcount and putreal.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

enum { F3, E3, P3 };

static struct {
	unsigned long long nodes, leaves[3];
} lev3[QT_MAXLEVEL + 1];

static struct {
	struct universe3 u;
	int		 haveu, deepest;
	unsigned long long nshells, ncavities, nfaces;
	long		 nobjects;	/* a combined stream's (qtbool) */
	struct xsum	 vol6;		/* six times the volume, exactly */
	double		 area, mx, my, mz;	/* area; 24 times moments */
} s3 = { .deepest = -1 };

/*
 * A shell's part of the solid's volume, area and moments: over its
 * triangles a, b, c, det[a, b, c] (six times the signed volume of the
 * tetrahedron from the origin, summed exactly), |(b - a) x (c - a)| / 2,
 * and det[a, b, c] (a + b + c) for the first moments.
 */
static void
shell3(const struct shell *g)
{
	size_t k;

	s3.nshells++;
	s3.ncavities += g->cavity;
	s3.nfaces += g->nt;
	for (k = 0; k < g->nt; k++) {
		struct point3 a = g->v[g->t[3 * k]], b = g->v[g->t[3 * k + 1]];
		struct point3 c = g->v[g->t[3 * k + 2]];
		double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
		double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
		double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz;
		double nz = ux * vy - uy * vx, d;

		area_addprod3(&s3.vol6, a.x, b.y, c.z);
		area_addprod3(&s3.vol6, -a.x, b.z, c.y);
		area_addprod3(&s3.vol6, -a.y, b.x, c.z);
		area_addprod3(&s3.vol6, a.y, b.z, c.x);
		area_addprod3(&s3.vol6, a.z, b.x, c.y);
		area_addprod3(&s3.vol6, -a.z, b.y, c.x);
		d = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z -
		    b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
		s3.area += sqrt(nx * nx + ny * ny + nz * nz) / 2;
		s3.mx += d * (a.x + b.x + c.x);
		s3.my += d * (a.y + b.y + c.y);
		s3.mz += d * (a.z + b.z + c.z);
	}
}

static void
cell3(const struct cell3 *c)
{
	if (c->level > s3.deepest)
		s3.deepest = c->level;
	if (c->class == 0)
		lev3[c->level].nodes++;
	else
		lev3[c->level].leaves[c->class == 'F' ? F3 : c->class == 'E' ?
		    E3 : P3]++;
}

/*
 * The volume of the leaves of the given classes in the tree cut at level
 * cut (its nodes there counted as partial leaves): the sum of n 8^-L over
 * the levels, exact, times the universe's side cubed.
 */
static double
leafvolume(int withpartial, int cut)
{
	struct xsum s;
	double v, side = s3.u.size;
	int l;

	area_init(&s);
	for (l = 0; l <= cut; l++) {
		unsigned long long n = lev3[l].leaves[F3];

		if (withpartial)
			n += lev3[l].leaves[P3] + (l == cut ? lev3[l].nodes : 0);
		/* n < 2^64 in two exact parts, each times 2^-3L */
		area_add(&s, ldexp((double)(n >> 32), 32 - 3 * l));
		area_add(&s, ldexp((double)(n & 0xffffffff), -3 * l));
	}
	v = area_round(&s) * side * side * side;
	area_free(&s);
	return v;
}

static void
report3(int table)
{
	double vol = area_round(&s3.vol6) / 6;
	unsigned long long nodes = 0, leaves[3] = { 0, 0, 0 };
	int l, k;

	if (s3.nobjects > 0)
		putcount("objects", s3.nobjects);
	putcount("shells", s3.nshells);
	putcount("cavities", s3.ncavities);
	putcount("faces", s3.nfaces);
	if (s3.nobjects > 0)
		printf("# left out, the shells bound %ld objects combined: "
		    "polyhedron_volume surface_area centroid_x centroid_y "
		    "centroid_z\n", s3.nobjects);
	else if (s3.nshells > 0) {
		putreal("polyhedron_volume", vol);
		putreal("surface_area", s3.area);
		if (vol != 0) {
			putreal("centroid_x", s3.mx / (24 * vol));
			putreal("centroid_y", s3.my / (24 * vol));
			putreal("centroid_z", s3.mz / (24 * vol));
		}
	}
	if (s3.haveu)
		putcount("universe_deepest_level", univ3deepest(&s3.u));
	if (s3.deepest < 0)
		return;
	for (l = 0; l <= s3.deepest; l++) {
		nodes += lev3[l].nodes;
		for (k = 0; k < 3; k++)
			leaves[k] += lev3[l].leaves[k];
	}
	putcount("cells", nodes + leaves[F3] + leaves[E3] + leaves[P3]);
	putcount("nodes", nodes);
	putcount("leaves", leaves[F3] + leaves[E3] + leaves[P3]);
	putcount("leaves_F", leaves[F3]);
	putcount("leaves_E", leaves[E3]);
	putcount("leaves_P", leaves[P3]);
	putcount("deepest_level", s3.deepest);
	putreal("volume_full", leafvolume(0, s3.deepest));
	putreal("volume_full_partial", leafvolume(1, s3.deepest));
	if (!table)
		return;
	printf("# level cells nodes leaves leaves_F leaves_E leaves_P\n");
	for (l = 0; l <= s3.deepest; l++) {
		unsigned long long n = lev3[l].leaves[F3] + lev3[l].leaves[E3] +
		    lev3[l].leaves[P3];

		printf("level %d %llu %llu %llu %llu %llu %llu\n", l,
		    lev3[l].nodes + n, lev3[l].nodes, n, lev3[l].leaves[F3],
		    lev3[l].leaves[E3], lev3[l].leaves[P3]);
	}
	printf("# cut level leaves_F leaves_E leaves_P volume_full "
	    "volume_full_partial\n");
	for (l = 0; l <= s3.deepest; l++) {
		unsigned long long n[3] = { 0, 0, 0 };
		char b1[32], b2[32];
		int m;

		for (m = 0; m <= l; m++)
			for (k = 0; k < 3; k++)
				n[k] += lev3[m].leaves[k];
		n[P3] += lev3[l].nodes;
		fmtreal(b1, leafvolume(0, l));
		fmtreal(b2, leafvolume(1, l));
		printf("cut %d %llu %llu %llu %s %s\n", l, n[F3], n[E3], n[P3],
		    b1, b2);
	}
}

int
stats3main(struct qtreader *r, int table)
{
	struct qt3reader *s = qt3_open(r);
	struct qt3rec rec;

	area_init(&s3.vol6);
	while (qt3_read(s, &rec) != QT_EOF)
		switch (rec.kind) {
		case QT_UNIVERSE:
			s3.u = rec.u;
			s3.haveu = 1;
			break;
		case QT_OBJECT:
			s3.nobjects = rec.object;
			break;
		case QT_SHELL:
			shell3(&rec.shell);
			break;
		case QT_NODE:
		case QT_LEAF:
			cell3(&rec.c);
			break;
		default:
			break;
		}
	qt3_close(s);
	qt_close(r);
	report3(table);
	area_free(&s3.vol6);
	closeout();
	return 0;
}
