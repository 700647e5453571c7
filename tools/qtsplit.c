/*
 * qtsplit: decompose the region of a qtree(5) stream into a quadtree.
 *
 * A cell is partial when an edge meets its open interior.  Each cell gets
 * the edges of its parent that meet it (exact orientation of the edge
 * against the cell's corners), so a cell costs in proportion to the edges
 * near it.  A cell without edges is full or empty by the even-odd parity of
 * a point just inside its lower-left corner, carried from the parent: the
 * parity changes once for every parent edge that crosses the short path
 * between the two points, and only the parent's edges can.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

struct edge {
	double	ax, ay, bx, by;
	double	xmin, ymin, xmax, ymax;
};

/* What the options ask for; maxlevel is -1 until the stream is read. */
static struct options {
	int	minlevel, maxlevel;
	int	verbose;
} opt = { .maxlevel = -1 };

/*
 * The stream: its universe, its rings' edges, and its records to write as
 * read, rings first.
 */
static struct input {
	struct universe	 u;
	int		 level;		/* of its level record; -1 for none */
	struct edge	*edges;
	size_t		 nedges;
	struct qtrec	**rings, **others;
	size_t		 nrings, nothers;
} in = { .level = -1 };

/* Per level: the cell's edges and, per edge, the children it meets. */
struct worklist {
	uint32_t	*edges;		/* into in.edges */
	unsigned char	*masks;
	size_t		 cap;
};

/* The walk down the tree, in preorder, and what it has written. */
static struct walk {
	double		 step[QT_MAXLEVEL + 1];	/* cell size by level */
	struct worklist	 list[QT_MAXLEVEL + 2];
	char		 path[QT_MAXLEVEL + 2];	/* of the cell at hand */
	unsigned long long ncells;
	int		 deepest;
} walk;

static void
usage(void)
{
	fprintf(stderr, "usage: qtsplit [-v] [-l level] [-m level] [-r path] "
	    "[file]\n");
	exit(2);
}

static int
orient(const struct edge *e, double x, double y)
{
	return orient2d(e->ax, e->ay, e->bx, e->by, x, y);
}

/* The side of e on which (x, y) + (d, d^2) lies, d > 0 infinitesimal. */
static int
nudged(const struct edge *e, int o)
{
	if (o != 0)
		return o;
	if (e->ay != e->by)
		return e->by > e->ay ? -1 : 1;
	return e->bx > e->ax ? 1 : -1;
}

static void
reserve(int level, size_t n)
{
	struct worklist *l = &walk.list[level];

	if (n <= l->cap)
		return;
	l->cap = n + n / 2 + 16;
	l->edges = xreallocarray(l->edges, l->cap, sizeof(*l->edges));
	l->masks = xreallocarray(l->masks, l->cap, sizeof(*l->masks));
}

static void
keep(struct qtrec ***list, size_t *n, const struct qtrec *rec)
{
	*list = xreallocarray(*list, *n + 1, sizeof(**list));
	(*list)[(*n)++] = qt_keep(rec);
}

static void
report(int force)
{
	if (opt.verbose)
		progress(force, "%llu cells, deepest level %d", walk.ncells,
		    walk.deepest);
}

/* Writes a cell; class 0 for a node. */
static void
emit(int level, uint64_t ix, uint64_t iy, char class)
{
	struct cell c;

	c.path = level > 0 ? walk.path : ".";
	c.level = level;
	c.ix = ix;
	c.iy = iy;
	c.class = class;
	c.text = NULL;
	qt_cell(&c, 0);
	if (level > walk.deepest)
		walk.deepest = level;
	if ((++walk.ncells & 0xfffff) == 0)
		report(0);
}

/*
 * Sorts the edges of cell (level, ix, iy) into its children: the level's
 * masks get, per edge, a bit for each child whose open interior it meets.  The
 * parities of the children's reference points go to parity[0..3].
 */
static void
children(int level, uint64_t ix, uint64_t iy, size_t n, int inside,
    int parity[4])
{
	const uint32_t *list = walk.list[level].edges;
	unsigned char *mask = walk.list[level].masks;
	double gx[3], gy[3];
	int bottom = 0, left = 0, middle = 0;
	size_t k;

	for (k = 0; k < 3; k++) {
		gx[k] = in.u.x0 + (double)(2 * ix + k) * walk.step[level + 1];
		gy[k] = in.u.y0 + (double)(2 * iy + k) * walk.step[level + 1];
	}
	for (k = 0; k < n; k++) {
		const struct edge *e = &in.edges[list[k]];
		/* orientation at grid point (i, j) in s[3 * j + i]; 2: unknown */
		signed char s[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 };
		int inx[2], iny[2], q, m = 0;

		inx[0] = e->xmin < gx[1] && e->xmax > gx[0];
		inx[1] = e->xmin < gx[2] && e->xmax > gx[1];
		iny[0] = e->ymin < gy[1] && e->ymax > gy[0];
		iny[1] = e->ymin < gy[2] && e->ymax > gy[1];
		/*
		 * Most edges, once cells are larger than they are, lie
		 * strictly inside one child: they meet it and no other, and
		 * cross none of the parity paths, which run along the
		 * children's sides.
		 */
		if (inx[0] != inx[1] && iny[0] != iny[1]) {
			int i = inx[1], j = iny[1];

			if (e->xmin > gx[i] && e->xmax < gx[i + 1] &&
			    e->ymin > gy[j] && e->ymax < gy[j + 1]) {
				mask[k] = 1 << (2 * j + i);
				continue;
			}
		}
		for (q = 0; q < 4; q++) {
			int i = q & 1, j = q >> 1, pos = 0, neg = 0, c;

			if (!inx[i] || !iny[j])
				continue;
			for (c = 0; c < 4; c++) {
				int gi = i + (c & 1), gj = j + (c >> 1);
				signed char *o = &s[3 * gj + gi];

				if (*o == 2)
					*o = orient(e, gx[gi], gy[gj]);
				pos |= *o > 0;
				neg |= *o < 0;
			}
			if (pos && neg)
				m |= 1 << q;
		}
		mask[k] = m;
		/*
		 * Crossings of the paths from the parent's point to the
		 * children's: along the bottom to the middle, up the left
		 * side, and up the middle line.
		 */
		if ((e->ay > gy[0]) != (e->by > gy[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			bottom ^= nudged(e, s[0]) != nudged(e, s[1]);
		}
		if ((e->ax > gx[0]) != (e->bx > gx[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[3] == 2)
				s[3] = orient(e, gx[0], gy[1]);
			left ^= nudged(e, s[0]) != nudged(e, s[3]);
		}
		if ((e->ax > gx[1]) != (e->bx > gx[1])) {
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			if (s[4] == 2)
				s[4] = orient(e, gx[1], gy[1]);
			middle ^= nudged(e, s[1]) != nudged(e, s[4]);
		}
	}
	parity[0] = inside;
	parity[1] = inside ^ bottom;
	parity[2] = inside ^ left;
	parity[3] = parity[1] ^ middle;
}

/* Moves the edges of child q from the level's list to the next level's. */
static size_t
childlist(int level, size_t n, int q)
{
	const uint32_t *list = walk.list[level].edges;
	const unsigned char *mask = walk.list[level].masks;
	uint32_t *out;
	size_t k, m = 0;

	reserve(level + 1, n);
	out = walk.list[level + 1].edges;
	for (k = 0; k < n; k++)
		if (mask[k] >> q & 1)
			out[m++] = list[k];
	return m;
}

static int
splits(int level, size_t n)
{
	return level < opt.minlevel || (n > 0 && level < opt.maxlevel);
}

/* Writes the cell and its subtree; its edges are list[level].edges[0..n-1]. */
static void
visit(int level, uint64_t ix, uint64_t iy, size_t n, int inside)
{
	int parity[4], q;

	if (!splits(level, n)) {
		emit(level, ix, iy, n > 0 ? 'P' : inside ? 'F' : 'E');
		return;
	}
	emit(level, ix, iy, 0);
	if (n > 0)
		children(level, ix, iy, n, inside, parity);
	else
		parity[0] = parity[1] = parity[2] = parity[3] = inside;
	for (q = 0; q < 4; q++) {
		size_t m = n > 0 ? childlist(level, n, q) : 0;

		walk.path[level] = '0' + q;
		walk.path[level + 1] = '\0';
		visit(level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1), m,
		    parity[q]);
	}
	walk.path[level] = '\0';
}

/* Even-odd parity of the universe's reference point, by a ray to +x. */
static int
rootparity(void)
{
	size_t i;
	int inside = 0;

	for (i = 0; i < in.nedges; i++) {
		const struct edge *e = &in.edges[i];
		int s;

		if ((e->ay > in.u.y0) == (e->by > in.u.y0))
			continue;
		s = nudged(e, orient(e, in.u.x0, in.u.y0));
		if (e->by > e->ay ? s > 0 : s < 0)
			inside ^= 1;
	}
	return inside;
}

/* The edges that meet the universe's open interior. */
static size_t
rootlist(void)
{
	double x1 = in.u.x0 + in.u.size, y1 = in.u.y0 + in.u.size;
	size_t i, n = 0;

	reserve(0, in.nedges);
	for (i = 0; i < in.nedges; i++) {
		const struct edge *e = &in.edges[i];
		int o[4], c, pos = 0, neg = 0;

		if (!(e->xmin < x1 && e->xmax > in.u.x0 && e->ymin < y1 &&
		    e->ymax > in.u.y0))
			continue;
		o[0] = orient(e, in.u.x0, in.u.y0);
		o[1] = orient(e, x1, in.u.y0);
		o[2] = orient(e, in.u.x0, y1);
		o[3] = orient(e, x1, y1);
		for (c = 0; c < 4; c++) {
			pos |= o[c] > 0;
			neg |= o[c] < 0;
		}
		if (pos && neg)
			walk.list[0].edges[n++] = i;
	}
	return n;
}

static void
addring(const struct ring *ring)
{
	size_t i, nv = ring->n;

	in.edges = xreallocarray(in.edges, in.nedges + nv, sizeof(*in.edges));
	for (i = 0; i < nv; i++) {
		struct edge *e = &in.edges[in.nedges++];
		struct point a = ring->v[i], b = ring->v[(i + 1) % nv];

		e->ax = a.x, e->ay = a.y, e->bx = b.x, e->by = b.y;
		e->xmin = fmin(a.x, b.x), e->xmax = fmax(a.x, b.x);
		e->ymin = fmin(a.y, b.y), e->ymax = fmax(a.y, b.y);
	}
}

/*
 * Reads the stream: its universe, its level, the rings' edges; the rings
 * and any other records are kept to be written as read, rings first.
 */
static void
readrings(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			in.u = rec.u;
			break;
		case QT_LEVEL:
			in.level = rec.level;
			break;
		case QT_RING:
			addring(&rec.ring);
			keep(&in.rings, &in.nrings, &rec);
			break;
		case QT_NODE:
		case QT_LEAF:
			qt_fail(r, "the input already holds cells: qtsplit "
			    "takes rings");
			break;
		default:
			keep(&in.others, &in.nothers, &rec);
			break;
		}
	}
	if (in.nedges > UINT32_MAX)
		die(1, "too many edges: %zu", in.nedges);
}

static void
writehead(void)
{
	size_t i;

	qt_header();
	qt_universe(&in.u);
	qt_level(opt.maxlevel);
	for (i = 0; i < in.nrings; i++) {
		qt_echo(in.rings[i]);
		qt_free(in.rings[i]);
	}
	for (i = 0; i < in.nothers; i++) {
		qt_echo(in.others[i]);
		qt_free(in.others[i]);
	}
}

/*
 * Walks down to the cell at path, as visit would, leaving its edges in
 * list[depth].edges[0..*n-1] and its parity in *inside; returns its depth.
 */
static int
descend(const char *subtree, uint64_t *ix, uint64_t *iy, size_t *n,
    int *inside)
{
	int depth = strlen(subtree), i;

	if (strcmp(subtree, ".") == 0)
		return 0;
	if (depth > QT_MAXLEVEL || pathcell(subtree, depth, ix, iy) < 0)
		die(2, "-r: not a cell path: %s", subtree);
	for (i = 0; i < depth; i++) {
		int parity[4], q = subtree[i] - '0';

		if (!splits(i, *n))
			die(1, "-r: no cell %s in the tree: cell %.*s is a leaf",
			    subtree, i > 0 ? i : 1, i > 0 ? subtree : ".");
		if (*n > 0)
			children(i, *ix >> (depth - i), *iy >> (depth - i), *n,
			    *inside, parity);
		else
			parity[q] = *inside;
		*n = *n > 0 ? childlist(i, *n, q) : 0;
		*inside = parity[q];
		walk.path[i] = subtree[i];
	}
	walk.path[depth] = '\0';
	return depth;
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	const char *end, *subtree = ".";
	long long val;
	uint64_t ix = 0, iy = 0;
	size_t n;
	int ch, inside, level, i;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "l:m:r:v")) != -1)
		switch (ch) {
		case 'l':
		case 'm':
			if (parselong(optarg, &end, &val) < 0 || *end != '\0' ||
			    val < 0 || val > QT_MAXLEVEL)
				die(2, "-%c: level must be an integer from 0 "
				    "to %d: %s", ch, QT_MAXLEVEL, optarg);
			if (ch == 'l')
				opt.maxlevel = val;
			else
				opt.minlevel = val;
			break;
		case 'r':
			subtree = optarg;
			break;
		case 'v':
			opt.verbose = 1;
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage();

	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_NEEDUNIVERSE);
	readrings(r);
	qt_close(r);
	if (opt.maxlevel < 0)
		opt.maxlevel = in.level >= 0 ? in.level : 6;
	if (opt.minlevel > opt.maxlevel)
		die(2, "-m %d is deeper than the maximum level %d",
		    opt.minlevel, opt.maxlevel);
	for (i = 0; i <= QT_MAXLEVEL; i++)
		walk.step[i] = ldexp(in.u.size, -i);

	writehead();
	inside = rootparity();
	n = rootlist();
	level = descend(subtree, &ix, &iy, &n, &inside);
	visit(level, ix, iy, n, inside);
	qt_end();
	report(1);
	closeout();
	return 0;
}
