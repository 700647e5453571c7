/*
 * inp.c: the mesh as an Abaqus input deck, as CalculiX reads it: the
 * nodes, the elements by type, the element sets EALL and one per leaf
 * class, and for the boundary the node sets and element-face surfaces a
 * user names in *BOUNDARY, *CLOAD or *DSLOAD after an *INCLUDE: with -b
 * one per ring (Rr) and one per edge of a ring (RrEk), else BOUNDARY.  A
 * surface's faces are found from the directed sides of the elements: a
 * boundary side a -> b is side k of one element alone, face Sk+1.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/*
 * The element families of -e: the types of triangles and quads, first
 * order and (-2) second.
 */
static const struct family {
	const char	*name;
	const char	*type[2][2];
} families[] = {
	{ "CPS",	{ { "CPS3", "CPS4" }, { "CPS6", "CPS8" } } },
	{ "CPE",	{ { "CPE3", "CPE4" }, { "CPE6", "CPE8" } } },
	{ "CAX",	{ { "CAX3", "CAX4" }, { "CAX6", "CAX8" } } },
	{ "DC2D",	{ { "DC2D3", "DC2D4" }, { "DC2D6", "DC2D8" } } },
};
#define NFAMILIES	(sizeof(families) / sizeof(families[0]))

int
inpfamily(const char *name)
{
	size_t i;

	for (i = 0; i < NFAMILIES; i++)
		if (strcmp(name, families[i].name) == 0)
			return (int)i;
	die(2, "-e: unknown element family %s (CPS, CPE, CAX or DC2D)", name);
	return -1;
}

/* Numbers and words into one line of the deck, each with ", " between. */
struct line {
	char	buf[512], *p;
};

static void
startline(struct line *l)
{
	l->p = l->buf;
}

static void
putint(struct line *l, long long v)
{
	if (l->p > l->buf) {
		*l->p++ = ',';
		*l->p++ = ' ';
	}
	l->p = fmtint(l->p, v);
}

/*
 * s with its exponent's '+' and leading zeros dropped, and the zeros
 * that end its digits before it: "1.50e-05" as "1.5e-5".
 */
static void
squeeze(char *s)
{
	char *e = strchr(s, 'e'), *d, *w;

	if (e == NULL)
		return;
	for (w = e; w > s && w[-1] == '0'; w--)
		continue;
	if (w > s && w[-1] == '.')
		w--;
	*w++ = 'e';
	d = e + 1;
	if (*d == '-')
		*w++ = *d++;
	else if (*d == '+')
		d++;
	while (*d == '0' && d[1] != '\0')
		d++;
	memmove(w, d, strlen(d) + 1);
}

/*
 * CalculiX reads a number from its first 20 characters (a Fortran f20.0
 * field) and refuses a longer one: v in the shortest digits that read
 * back when they fit, else rounded to the most digits that do (16 or 15,
 * a relative error under 5e-16).  Where no setlocale is called, printf's
 * decimal point is the C locale's.
 */
#define INPWIDTH	20

static char *
inpreal(char *p, double v)
{
	char s[40];
	int d;

	fmtreal(s, v);
	squeeze(s);
	for (d = 16; strlen(s) > INPWIDTH && d > 1; d--) {
		snprintf(s, sizeof(s), "%.*e", d - 1, v);
		squeeze(s);
	}
	return stpcpy(p, s);
}

static void
putreal(struct line *l, double v)
{
	if (l->p > l->buf) {
		*l->p++ = ',';
		*l->p++ = ' ';
	}
	l->p = inpreal(l->p, v);
}

static void
endline(struct line *l)
{
	*l->p++ = '\n';
	if (fwrite(l->buf, 1, l->p - l->buf, stdout) != (size_t)(l->p - l->buf))
		die(1, "write error");
	l->p = l->buf;
}

/* A list of numbers, eight a line, as the deck's sets take them. */
static void
putlist(const uint32_t *v, size_t n)
{
	struct line l;
	size_t i;

	startline(&l);
	for (i = 0; i < n; i++) {
		putint(&l, v[i]);
		if (i % 8 == 7 || i + 1 == n)
			endline(&l);
	}
}

static int
cmpu32(const void *va, const void *vb)
{
	uint32_t a = *(const uint32_t *)va, b = *(const uint32_t *)vb;

	return (a > b) - (a < b);
}

/* The numbers of v sorted, each once: their count. */
static size_t
uniq(uint32_t *v, size_t n)
{
	size_t i, w = 0;

	if (n > 0)
		qsort(v, n, sizeof(*v), cmpu32);
	for (i = 0; i < n; i++)
		if (w == 0 || v[w - 1] != v[i])
			v[w++] = v[i];
	return w;
}

/* The elements' directed sides: to 4 e + k + 1 for side k of element e. */
static void
elemsides(const struct mesh *m, struct sidemap *sm)
{
	const struct elem *elems = m->elems;
	size_t i;
	int k, n;

	memset(sm, 0, sizeof(*sm));
	for (i = 0; i < m->nelems; i++)
		for (n = nverts(&elems[i]), k = 0; k < n; k++)
			sideput(sm, elems[i].v[k], elems[i].v[(k + 1) % n],
			    (uint32_t)(4 * i + k + 1));
}

static int
cmpseg(const void *va, const void *vb)
{
	const struct seg *a = va, *b = vb;

	if (a->ring != b->ring)
		return a->ring < b->ring ? -1 : 1;
	return (a->edge > b->edge) - (a->edge < b->edge);
}

/*
 * The node set and the surface of the boundary sides segs[0 .. n), named
 * name, their mid-side nodes with -2 (nv corners before them); buf has
 * room for 3 n numbers.
 */
static void
boundaryset(const struct mesh *m, size_t nv, const struct sidemap *sides,
    const struct seg *segs, size_t n, const char *name, uint32_t *buf)
{
	struct line l;
	size_t i, nn = 0;
	uint32_t face;

	for (i = 0; i < n; i++) {
		buf[nn++] = m->perm[segs[i].a - 1];
		buf[nn++] = m->perm[segs[i].b - 1];
		if (m->order == 2)
			buf[nn++] = (uint32_t)(nv + segmid(m, &segs[i]));
	}
	nn = uniq(buf, nn);
	printf("*NSET, NSET=%s\n", name);
	putlist(buf, nn);
	printf("*SURFACE, NAME=%s, TYPE=ELEMENT\n", name);
	for (i = 0; i < n; i++) {
		face = sideget(sides, segs[i].a, segs[i].b);
		if (face == 0)
			die(1, "internal error: boundary side in no element");
		startline(&l);
		putint(&l, (face - 1) / 4 + 1);
		l.p += sprintf(l.p, ", S%u", (unsigned)((face - 1) % 4 + 1));
		endline(&l);
	}
}

/* The sets of each ring, Rr, and of each of its edges, RrEk. */
static void
ringsets(const struct mesh *m, size_t nv, const struct sidemap *sides,
    struct seg *segs, uint32_t *buf)
{
	char name[64];
	size_t i, j, k, e;

	qsort(segs, m->nsegs, sizeof(*segs), cmpseg);
	for (i = 0; i < m->nsegs; i = j) {
		for (j = i; j < m->nsegs && segs[j].ring == segs[i].ring; j++)
			continue;
		snprintf(name, sizeof(name), "R%lu",
		    (unsigned long)segs[i].ring);
		boundaryset(m, nv, sides, segs + i, j - i, name, buf);
		for (k = i; k < j; k = e) {
			for (e = k; e < j && segs[e].edge == segs[k].edge; e++)
				continue;
			snprintf(name, sizeof(name), "R%luE%lu",
			    (unsigned long)segs[k].ring,
			    (unsigned long)segs[k].edge);
			boundaryset(m, nv, sides, segs + k, e - k, name,
			    buf);
		}
	}
}

/* The boundary's sets: ring by ring and edge by edge, or the one set. */
static void
boundarysets(const struct mesh *m, size_t nv)
{
	struct seg *segs;
	struct sidemap sides;
	uint32_t *buf;

	if (m->nsegs == 0)
		return;
	elemsides(m, &sides);
	buf = xreallocarray(NULL, 3 * m->nsegs, sizeof(*buf));
	segs = xreallocarray(NULL, m->nsegs, sizeof(*segs));
	memcpy(segs, m->segs, m->nsegs * sizeof(*segs));
	if (!m->bfit)
		boundaryset(m, nv, &sides, segs, m->nsegs, "BOUNDARY", buf);
	else
		ringsets(m, nv, &sides, segs, buf);
	free(sides.slot);
	free(segs);
	free(buf);
}

/* The elements of the class class ('F', 'P' or 'E') as a set, if any. */
static void
classset(const struct mesh *m, int class, const char *name, uint32_t *buf)
{
	size_t i, j, e, n = 0;

	for (i = e = 0; i < m->nleaves; i++)
		for (j = 0; j < leafnel(m, i); j++, e++)
			if (m->leaves[i].class == class)
				buf[n++] = (uint32_t)e + 1;
	if (n == 0)
		return;
	printf("*ELSET, ELSET=%s\n", name);
	putlist(buf, n);
}

void
writeinp(const struct mesh *m, size_t nv, const uint32_t *inv)
{
	const struct family *f = &families[m->family];
	const struct elem *elems = m->elems;
	struct line l;
	long long v[8];
	uint32_t *buf;
	double xy[2];
	size_t i, k, n;
	int pass;

	printf("*HEADING\n%s\n*NODE, NSET=NALL\n", m->command);
	for (i = 0; i < nv + m->nmid; i++) {
		nodexy(m, nv, inv, i, xy);
		startline(&l);
		putint(&l, (long long)i + 1);
		putreal(&l, xy[0]);
		putreal(&l, xy[1]);
		endline(&l);
	}
	/* triangles, then quads, each element with its number in the mesh */
	for (pass = 3; pass <= 4; pass++) {
		for (i = 0; i < m->nelems && nverts(&elems[i]) != pass; i++)
			continue;
		if (i == m->nelems)
			continue;
		printf("*ELEMENT, TYPE=%s, ELSET=EALL\n",
		    f->type[m->order - 1][pass - 3]);
		for (; i < m->nelems; i++) {
			if (nverts(&elems[i]) != pass)
				continue;
			n = elemnodes(m, i, nv, v);
			startline(&l);
			putint(&l, (long long)i + 1);
			for (k = 0; k < n; k++)
				putint(&l, v[k]);
			endline(&l);
		}
	}
	buf = xreallocarray(NULL, m->nelems + 1, sizeof(*buf));
	classset(m, 'F', "FULL", buf);
	classset(m, 'P', "PARTIAL", buf);
	classset(m, 'E', "EMPTY", buf);
	free(buf);
	boundarysets(m, nv);
}
