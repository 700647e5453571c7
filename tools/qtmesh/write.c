/*
 * write.c: the mesh written, one function a format, each of nv vertices
 * in the order inv gives and with the numbers perm gives: a qtree(5)
 * stream (the leaves, then vertex, elem and hang records), Gmsh 2.2, VTK
 * legacy and Shewchuk's Triangle files.  main.c picks the writer from its
 * table.  The qtree stream goes through lib/write.c; the other formats
 * write their lines of numbers by putline, each number by fmtint or
 * fmtreal, so that a coordinate reads back as the double it was.  The
 * cells' paths are made here as well, the stream's from the path before,
 * and lent to the other files for messages.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/* Digit d of the path of the cell at ix, iy of level. */
static char
pathdigit(int level, int d, uint64_t ix, uint64_t iy)
{
	int b = level - 1 - d;

	return '0' + (int)(2 * (iy >> b & 1) + (ix >> b & 1));
}

char *
cellpath(char *path, int level, uint64_t ix, uint64_t iy)
{
	int d;

	if (level == 0)
		return strcpy(path, ".");
	for (d = 0; d < level; d++)
		path[d] = pathdigit(level, d, ix, iy);
	path[level] = '\0';
	return path;
}

/*
 * The path of leaf l written over that of leaf p, the one before it: in
 * preorder the two mostly part only in their last digits, from the
 * highest bit where their columns or rows differ at the coarser level.
 */
static char *
nextpath(char *path, const struct leaf *p, const struct leaf *l)
{
	int m = l->level < p->level ? l->level : p->level, d = m;
	uint64_t diff = (l->ix >> (l->level - m) ^ p->ix >> (p->level - m)) |
	    (l->iy >> (l->level - m) ^ p->iy >> (p->level - m));

	if (l->level == 0 || p->level == 0)
		return cellpath(path, l->level, l->ix, l->iy);
	for (; diff != 0; diff >>= 1)
		d--;
	for (; d < l->level; d++)
		path[d] = pathdigit(l->level, d, l->ix, l->iy);
	path[l->level] = '\0';
	return path;
}

/* The number of leaf i's elements. */
size_t
leafnel(const struct mesh *m, size_t i)
{
	return m->bfit ? m->b.elstart[i + 1] - m->b.elstart[i] :
	    m->leaves[i].nel;
}

static double
gridcoord(const struct universe *u, int axis, uint64_t i)
{
	return cell_coord(axis ? u->y0 : u->x0, u->size, QT_GRID, i);
}

/* One line of numbers: integers, then reals, into fp. */
static void
putline(FILE *fp, const long long *iv, int ni, const double *rv, int nr,
    const char *tail)
{
	char buf[64 * 12], *p = buf;
	int i;

	for (i = 0; i < ni; i++) {
		if (p > buf)
			*p++ = ' ';
		p = fmtint(p, iv[i]);
	}
	for (i = 0; i < nr; i++) {
		if (p > buf)
			*p++ = ' ';
		p = fmtreal(p, rv[i]);
	}
	p += strlen(strcpy(p, tail));
	*p++ = '\n';
	if (fwrite(buf, 1, p - buf, fp) != (size_t)(p - buf))
		die(1, "write error");
}

void
vertexxy(const struct mesh *m, uint32_t id, double *xy)
{
	uint64_t x, y;

	if (m->bfit) {
		xy[0] = m->b.bv[id - 1].x;
		xy[1] = m->b.bv[id - 1].y;
		return;
	}
	corner_point(m->g.vt, id, &x, &y);
	xy[0] = gridcoord(&m->u, 0, x);
	xy[1] = gridcoord(&m->u, 1, y);
}

static int
classtag(int class)
{
	return class == 'F' ? 1 : class == 'P' ? 2 : 4;
}

void
writeqtree(const struct mesh *m, size_t nv, const uint32_t *inv)
{
	const uint32_t *perm = m->perm;
	const struct elem *elems = m->elems;
	const struct hang *hangs = m->g.hangs;
	char path[QT_GRID + 2];
	unsigned long long v[4], first = 1;
	struct cell c;
	uint64_t x, y;
	size_t i;
	int k;

	for (i = 0; i < m->nleaves; i++) {
		const struct leaf *l = &m->leaves[i];

		memset(&c, 0, sizeof(c));
		c.level = l->level;
		c.ix = l->ix;
		c.iy = l->iy;
		c.class = l->class;
		c.path = i == 0 ? cellpath(path, l->level, l->ix, l->iy) :
		    nextpath(path, &m->leaves[i - 1], l);
		c.size = m->u.size;
		qt_cell(&c, first);
		first += leafnel(m, i);
	}
	for (i = 0; i < nv; i++)
		if (m->bfit)
			qt_vertex(i + 1, m->b.bv[inv[i] - 1].x,
			    m->b.bv[inv[i] - 1].y);
		else {
			corner_point(m->g.vt, inv[i], &x, &y);
			qt_gridvertex(i + 1, QT_GRID, x, y);
		}
	for (i = 0; i < m->nelems; i++) {
		for (k = 0; k < nverts(&elems[i]); k++)
			v[k] = perm[elems[i].v[k] - 1];
		qt_elem(i + 1, k == 4 ? "quad" : "tri", k, v);
	}
	for (i = 0; i < m->g.nhangs; i++)
		qt_hang(perm[hangs[i].v - 1], perm[hangs[i].a - 1],
		    perm[hangs[i].b - 1]);
	qt_end();
}

/*
 * -b: the elementary tag of boundary side sg, its ring edge's: R + E for
 * the stream's R rings and the E-th edge of all of them.
 */
static size_t
segtag(const struct mesh *m, const struct seg *sg)
{
	if (sg->ring == 0)
		return 0;
	return m->b.nrlen + m->b.redge[sg->ring - 1] + sg->edge;
}

/*
 * -b: the rings that boundary sides run along, each a physical group of
 * lines, "ring N" with tag N, written to fp unless NULL: their count.
 */
static size_t
ringtags(const struct mesh *m, FILE *fp)
{
	unsigned char *has = xcalloc(m->b.nrlen + 1, 1);
	size_t i, n = 0;

	for (i = 0; i < m->nsegs && m->bfit; i++)
		if (m->segs[i].ring != 0 && !has[m->segs[i].ring]) {
			has[m->segs[i].ring] = 1;
			n++;
		}
	for (i = 1; i <= m->b.nrlen && fp != NULL; i++)
		if (has[i])
			fprintf(fp, "1 %zu \"ring %zu\"\n", i, i);
	free(has);
	return n;
}

static void
mshnames(const struct mesh *m)
{
	size_t i;
	int tags[5] = { 0 };

	for (i = 0; i < m->nleaves; i++)
		tags[classtag(m->leaves[i].class)] = 1;
	tags[3] = m->nsegs > 0 && !m->bfit;
	printf("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n",
	    tags[1] + tags[2] + tags[3] + tags[4] + (int)ringtags(m, NULL));
	if (tags[3])
		printf("1 3 \"boundary\"\n");
	ringtags(m, stdout);
	if (tags[1])
		printf("2 1 \"full\"\n");
	if (tags[2])
		printf("2 2 \"partial\"\n");
	if (tags[4])
		printf("2 4 \"empty\"\n");
	printf("$EndPhysicalNames\n");
}

/*
 * The element types of Gmsh and VTK by order, first and second: a line,
 * a triangle and a quad.
 */
static const int mshtype[2][3] = { { 1, 2, 3 }, { 8, 9, 16 } };
static const int vtktype[2][3] = { { 3, 5, 9 }, { 21, 22, 23 } };

void
writemsh(const struct mesh *m, size_t nv, const uint32_t *inv)
{
	const uint32_t *perm = m->perm;
	long long iv[5 + 8];
	double xy[3];
	size_t i, e = 0, j, id = 0, n;

	mshnames(m);
	printf("$Nodes\n%zu\n", nv + m->nmid);
	for (i = 0; i < nv + m->nmid; i++) {
		iv[0] = i + 1;
		nodexy(m, nv, inv, i, xy);
		xy[2] = 0;
		putline(stdout, iv, 1, xy, 3, "");
	}
	printf("$EndNodes\n$Elements\n%zu\n", m->nelems + m->nsegs);
	for (i = 0; i < m->nleaves; i++)
		for (j = 0; j < leafnel(m, i); j++, e++) {
			n = elemnodes(m, e, nv, iv + 5);
			iv[0] = ++id;
			iv[1] = mshtype[m->order - 1][n / m->order - 2];
			iv[2] = 2;
			iv[3] = iv[4] = classtag(m->leaves[i].class);
			putline(stdout, iv, 5 + (int)n, NULL, 0, "");
		}
	for (i = 0; i < m->nsegs; i++) {
		const struct seg *sg = &m->segs[i];

		iv[0] = ++id;
		iv[1] = mshtype[m->order - 1][0];
		iv[2] = 2;
		iv[3] = m->bfit ? sg->ring : 3;
		iv[4] = m->bfit ? (long long)segtag(m, sg) : 3;
		iv[5] = perm[sg->a - 1];
		iv[6] = perm[sg->b - 1];
		iv[7] = (long long)nv + (m->order == 2 ? segmid(m, sg) : 0);
		putline(stdout, iv, 6 + m->order, NULL, 0, "");
	}
	printf("$EndElements\n");
}

void
writevtk(const struct mesh *m, size_t nv, const uint32_t *inv)
{
	const uint32_t *perm = m->perm;
	long long iv[1 + 8];
	double xy[3];
	size_t i, j, e, nref = 0, nline, n;
	int k, pass;

	printf("# vtk DataFile Version 3.0\nqtmesh\nASCII\n"
	    "DATASET UNSTRUCTURED_GRID\nPOINTS %zu double\n", nv + m->nmid);
	for (i = 0; i < nv + m->nmid; i++) {
		nodexy(m, nv, inv, i, xy);
		xy[2] = 0;
		putline(stdout, NULL, 0, xy, 3, "");
	}
	for (i = 0; i < m->nelems; i++)
		nref += 1 + m->order * nverts(&m->elems[i]);
	nline = m->bfit ? m->nsegs : 0;	/* -b: the boundary as lines */
	printf("CELLS %zu %zu\n", m->nelems + nline,
	    nref + (2 + m->order) * nline);
	for (i = 0; i < m->nelems; i++) {
		iv[0] = (long long)(n = elemnodes(m, i, nv, iv + 1));
		for (k = 1; k <= (int)n; k++)
			iv[k]--;
		putline(stdout, iv, 1 + (int)n, NULL, 0, "");
	}
	for (i = 0; i < nline; i++) {
		iv[0] = 1 + m->order;
		iv[1] = perm[m->segs[i].a - 1] - 1;
		iv[2] = perm[m->segs[i].b - 1] - 1;
		if (m->order == 2)
			iv[3] = (long long)nv + segmid(m, &m->segs[i]) - 1;
		putline(stdout, iv, 2 + m->order, NULL, 0, "");
	}
	printf("CELL_TYPES %zu\n", m->nelems + nline);
	for (i = 0; i < m->nelems; i++)
		printf("%d\n", vtktype[m->order - 1][nverts(&m->elems[i]) - 2]);
	for (i = 0; i < nline; i++)
		printf("%d\n", vtktype[m->order - 1][0]);
	printf("CELL_DATA %zu\n", m->nelems + nline);
	for (pass = 0; pass < (m->bfit ? 3 : 2); pass++) {
		printf("SCALARS %s int 1\nLOOKUP_TABLE default\n",
		    pass == 2 ? "ring" : pass ? "level" : "class");
		for (i = e = 0; i < m->nleaves; i++)
			for (j = 0; j < leafnel(m, i); j++, e++)
				printf("%d\n", pass == 2 ? 0 : pass ?
				    m->leaves[i].level :
				    classtag(m->leaves[i].class));
		for (i = 0; i < nline; i++)
			printf("%lu\n", pass == 2 ?
			    (unsigned long)m->segs[i].ring : 0UL);
	}
}

static FILE *
create(const char *outbase, const char *ext, char **name)
{
	FILE *fp;

	*name = xmalloc(strlen(outbase) + strlen(ext) + 1);
	strcat(strcpy(*name, outbase), ext);
	if ((fp = fopen(*name, "w")) == NULL)
		die(1, "%s: cannot create", *name);
	return fp;
}

static void
finish(FILE *fp, char *name)
{
	if (fflush(fp) == EOF || ferror(fp) || fclose(fp) == EOF)
		die(1, "%s: write error", name);
	free(name);
}

/* -b: BASE.poly, the boundary's sides, marked by ring. */
static void
writepoly(const struct mesh *m)
{
	long long iv[4];
	char *name;
	FILE *fp;
	size_t i;

	fp = create(m->outbase, ".poly", &name);
	fprintf(fp, "0 2 0 1\n%zu 1\n", m->nsegs);
	for (i = 0; i < m->nsegs; i++) {
		iv[0] = i + 1;
		iv[1] = m->perm[m->segs[i].a - 1];
		iv[2] = m->perm[m->segs[i].b - 1];
		iv[3] = m->segs[i].ring;
		putline(fp, iv, 4, NULL, 0, "");
	}
	fprintf(fp, "0\n");
	finish(fp, name);
}

/* Shewchuk's Triangle: BASE.node with boundary markers, BASE.ele. */
void
writetriangle(const struct mesh *m, size_t nv, const uint32_t *inv)
{
	const uint32_t *perm = m->perm;
	const struct elem *elems = m->elems;
	long long iv[5];
	double xy[2];
	char *name, tail[32];
	uint32_t *onb;
	FILE *fp;
	size_t i, j, e;
	int k;

	onb = xcalloc(nv + 1, sizeof(*onb));
	for (i = 0; i < m->nsegs; i++)
		onb[perm[m->segs[i].a - 1]] = onb[perm[m->segs[i].b - 1]] =
		    m->bfit ? m->segs[i].ring : 1;
	fp = create(m->outbase, ".node", &name);
	fprintf(fp, "%zu 2 0 1\n", nv);
	for (i = 0; i < nv; i++) {
		vertexxy(m, inv[i], xy);
		iv[0] = i + 1;
		tail[0] = ' ';
		fmtint(tail + 1, onb[i + 1]);
		putline(fp, iv, 1, xy, 2, tail);
	}
	finish(fp, name);
	if (m->bfit)
		writepoly(m);
	fp = create(m->outbase, ".ele", &name);
	fprintf(fp, "%zu 3 1\n", m->nelems);
	for (i = e = 0; i < m->nleaves; i++)
		for (j = 0; j < leafnel(m, i); j++, e++) {
			iv[0] = e + 1;
			for (k = 0; k < 3; k++)
				iv[1 + k] = perm[elems[e].v[k] - 1];
			iv[4] = classtag(m->leaves[i].class);
			putline(fp, iv, 5, NULL, 0, "");
		}
	finish(fp, name);
	free(onb);
}
