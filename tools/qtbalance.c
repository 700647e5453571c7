/*
 * qtbalance: refine a qtree(5) tree so that leaves sharing a side (with -c,
 * a side or a corner) differ by at most one level: the 2:1 balance of a
 * graded mesh; with -k K, so that the leaves of each level make a band at
 * least K of them wide between shallower leaves and deeper: a grading rate.
 *
 * A tree is balanced when every node's neighbours of its own level, across
 * a side (and a corner), are cells of the tree, nodes or leaves: a leaf two
 * levels above a cell it touches lies over such a missing neighbour of that
 * cell's parent, and conversely.  With -k K the neighbours are the cells of
 * the node's level within K of it, across and up, corners included.  So
 * each node is checked once, those of the input and those that splitting
 * makes, and a missing neighbour's parent is made a node by splitting the
 * leaf that holds it down to it.  Splits only add nodes, so a node checked
 * stays satisfied; the new nodes lie above the one checked, and the tree
 * gets no deeper.
 *
 * The tree is held as its nodes alone, in a cellset: a cell is in the tree
 * when its parent is a node, and each node's byte holds its four children's
 * codes, two bits each (0 a node, else the class of a leaf), so leaves cost
 * nothing of their own.  The children of a split leaf inherit an F or E
 * class; those of a P leaf are classified from the stream's rings by the
 * library's exact classifier, as qtsplit would.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

#define MAXRATE	64	/* -k's largest */

/* A child's code: 0 for a node, else a leaf's class. */
enum { NODE, FULL, EMPTY, PART };

static const char classof[4] = { 0, 'F', 'E', 'P' };

static struct options {
	int	corners, verbose;
	int	k;	/* -k: the neighbours' reach, in cells; 0 till chosen */
} opt;

/* The tree: its nodes, and the root's class when it is a leaf. */
static struct tree {
	struct cellset	*nodes;
	char		 rootclass;	/* 0: the root is a node */
	unsigned long long ncells, nnodes, nsplit;
	int		 depth;		/* the deepest cell's level */
	const char	*name;		/* of the input, for messages */
} t;

/* Per level, the node of the current path while the stream is read. */
static struct open {
	uint64_t	ix, iy;
	unsigned char	code;	/* the children's codes so far */
	unsigned char	seen;	/* a bit per child read */
	unsigned char	live;	/* awaiting children */
} open[QT_MAXLEVEL + 1];
static int openlevel = -1;	/* the deepest live one */

/* Nodes made and not yet checked, level above bit 56 of the column. */
static struct work {
	uint64_t	*cell;	/* ix | level << 56, then iy */
	size_t		 n, cap;
} work;

/*
 * The exact classifier and the last path it went down: the edges and
 * parity of each cell from the root to (depth, ix, iy).
 */
static struct classifier {
	struct splitter	*sp;
	int		 depth;	/* -1 before the first descent */
	uint64_t	 ix, iy;
	size_t		 n[QT_MAXLEVEL + 1];
	int		 inside[QT_MAXLEVEL + 1];
	size_t		 nrings;
	int		 combined;	/* object records: the rings of several */
} cl = { .depth = -1 };

static void
usage(int help)
{
	usageexit(help, "usage: qtbalance [-chv] [-k rate] [file]\n");
}

static int
codeof(char class)
{
	return class == 'F' ? FULL : class == 'E' ? EMPTY : PART;
}

/* The path of cell (level, ix, iy) in buf, QT_MAXLEVEL + 2 bytes. */
static const char *
pathof(char *buf, int level, uint64_t ix, uint64_t iy)
{
	int k;

	if (level == 0)
		return ".";
	for (k = 0; k < level; k++) {
		int s = level - 1 - k;

		buf[k] = '0' + (int)((iy >> s & 1) << 1 | (ix >> s & 1));
	}
	buf[level] = '\0';
	return buf;
}

/* The first child of a node that its bits of children read lack. */
static int
lacking(unsigned seen)
{
	int q;

	for (q = 0; q < 3 && (seen >> q & 1); q++)
		continue;
	return q;
}

static void
report(int force)
{
	if (opt.verbose)
		progress(force, "%llu cells read, %llu leaves split",
		    t.ncells, t.nsplit);
}

/*
 * Closes the nodes of the current path at level and below: each must have
 * had its four children.
 */
static void
closeopen(struct qtreader *r, int level)
{
	char buf[QT_MAXLEVEL + 2];
	int k;

	for (k = openlevel; k >= level; k--)
		if (open[k].live)
			qt_fail(r, "not a whole tree: node %s lacks child %d",
			    pathof(buf, k, open[k].ix, open[k].iy),
			    lacking(open[k].seen));
	if (openlevel >= level)
		openlevel = level - 1;
}

/* Takes a cell of the input into the tree, checking that the tree is whole. */
static void
addcell(struct qtreader *r, const struct cell *c)
{
	struct open *p;
	int q, code = c->class ? codeof(c->class) : NODE;

	if (t.ncells == 0 && c->level != 0)
		qt_fail(r, "not a whole tree: the first cell is %s, not the "
		    "root: qtbalance takes a tree with its nodes, as qtsplit "
		    "writes it", c->path);
	closeopen(r, c->level);
	t.ncells++;
	if (c->level > t.depth)
		t.depth = c->level;
	if (c->level == 0) {
		t.rootclass = c->class;
	} else {
		p = &open[c->level - 1];
		q = (int)((c->iy & 1) << 1 | (c->ix & 1));
		if (!p->live || p->ix != c->ix >> 1 || p->iy != c->iy >> 1)
			qt_fail(r, "not a whole tree: cell %s has no parent "
			    "node", c->path);
		if (p->seen != (1u << q) - 1)
			qt_fail(r, "not a whole tree: cell %s comes without "
			    "its sibling %d", c->path, lacking(p->seen));
		p->seen |= 1u << q;
		p->code |= code << 2 * q;
		if (q == 3) {
			cellset_put(t.nodes, c->level - 1, p->ix, p->iy,
			    p->code);
			p->live = 0;
		}
	}
	if (c->class == 0) {
		p = &open[c->level];
		p->ix = c->ix;
		p->iy = c->iy;
		p->code = p->seen = 0;
		p->live = 1;
		openlevel = c->level;
		t.nnodes++;
	}
}

static void
pushwork(int level, uint64_t ix, uint64_t iy)
{
	if (work.n + 2 > work.cap) {
		work.cap = work.cap ? 2 * work.cap : 1024;
		work.cell = xreallocarray(work.cell, work.cap,
		    sizeof(*work.cell));
	}
	work.cell[work.n++] = ix | (uint64_t)level << 56;
	work.cell[work.n++] = iy;
}

/* Brings the classifier's path down to cell (level, ix, iy). */
static void
descend(int level, uint64_t ix, uint64_t iy)
{
	int k, parity[4];

	if (cl.depth < 0) {
		cl.n[0] = split_root(cl.sp, &cl.inside[0]);
		cl.depth = 0;
		cl.ix = cl.iy = 0;
	}
	k = cl.depth < level ? cl.depth : level;
	while (k > 0 && ((cl.ix >> (cl.depth - k)) != (ix >> (level - k)) ||
	    (cl.iy >> (cl.depth - k)) != (iy >> (level - k))))
		k--;
	for (; k < level; k++) {
		int s = level - k - 1;
		int q = (int)((iy >> s & 1) << 1 | (ix >> s & 1));

		split_children(cl.sp, k, ix >> (s + 1), iy >> (s + 1), cl.n[k],
		    cl.inside[k], parity);
		cl.n[k + 1] = split_child(cl.sp, k, cl.n[k], q);
		cl.inside[k + 1] = parity[q];
	}
	cl.depth = level;
	cl.ix = ix;
	cl.iy = iy;
}

/* The codes of the children of the P leaf (level, ix, iy), from the rings. */
static unsigned
partchildren(int level, uint64_t ix, uint64_t iy)
{
	char buf[QT_MAXLEVEL + 2];
	unsigned code = 0;
	int parity[4], q;

	if (cl.combined)	/* the cells alone cannot decide */
		return PART | PART << 2 | PART << 4 | PART << 6;
	if (cl.nrings == 0)
		errat(t.name, 0, "leaf %s is partial and must be split, but "
		    "the stream has no rings to classify its children",
		    pathof(buf, level, ix, iy));
	descend(level, ix, iy);
	if (cl.n[level] == 0)
		errat(t.name, 0, "leaf %s is partial, but no edge of the "
		    "stream's rings meets it: the rings are not the tree's",
		    pathof(buf, level, ix, iy));
	split_children(cl.sp, level, ix, iy, cl.n[level], cl.inside[level],
	    parity);
	for (q = 0; q < 4; q++)
		code |= (unsigned)codeof(split_class(split_child(cl.sp, level,
		    cl.n[level], q), parity[q])) << 2 * q;
	return code;
}

/*
 * Makes cell (level, ix, iy) a node: the leaf that holds it, a child of the
 * node at level top, is split, and its descendants down to the cell.
 */
static void
splitdown(int top, int level, uint64_t ix, uint64_t iy)
{
	int j = top + 1, s = level - j, q;
	uint64_t px = ix >> (s + 1), py = iy >> (s + 1);
	unsigned parent = cellset_get(t.nodes, top, px, py), code;

	q = (int)((iy >> s & 1) << 1 | (ix >> s & 1));
	code = parent >> 2 * q & 3;
	cellset_put(t.nodes, top, px, py, parent & ~(3u << 2 * q));
	for (; j <= level; j++) {
		uint64_t cx, cy;
		unsigned children;

		s = level - j;
		cx = ix >> s;
		cy = iy >> s;
		children = code == PART ? partchildren(j, cx, cy) :
		    code * 0x55u;
		if (j < level) {
			s--;
			q = (int)((iy >> s & 1) << 1 | (ix >> s & 1));
			code = children >> 2 * q & 3;
			children &= ~(3u << 2 * q);
		}
		cellset_put(t.nodes, j, cx, cy, children);
		pushwork(j, cx, cy);
		t.nsplit++;
	}
}

/* Makes cell (level, ix, iy) a node, unless the universe ends first. */
static void
need(int level, uint64_t ix, uint64_t iy, int dx, int dy)
{
	uint64_t nx, ny;
	int top;

	if (!cellset_next(level, ix, iy, dx, dy, &nx, &ny))
		return;
	top = cellset_above(t.nodes, level, nx, ny);
	if (top < level)
		splitdown(top, level, nx, ny);
}

/*
 * Makes the cells of level within K of node (level, ix, iy) cells of the
 * tree, K = -k's rate: makes their parents nodes, the cells of level - 1
 * from (ix - K) / 2 to (ix + K) / 2 across and as many up, K + 1 by K + 1
 * within the universe, each looked up once.
 */
static void
checkblock(int level, uint64_t ix, uint64_t iy)
{
	uint64_t last = (UINT64_C(1) << level) - 1, k = (uint64_t)opt.k;
	uint64_t x0 = (ix > k ? ix - k : 0) >> 1, y0 = (iy > k ? iy - k : 0) >> 1;
	uint64_t x1 = (last - ix > k ? ix + k : last) >> 1;
	uint64_t y1 = (last - iy > k ? iy + k : last) >> 1;
	uint64_t px, py;

	for (py = y0; py <= y1; py++)
		for (px = x0; px <= x1; px++) {
			int top = cellset_above(t.nodes, level - 1, px, py);

			if (top < level - 1)
				splitdown(top, level - 1, px, py);
		}
}

/*
 * Makes the neighbours of node (level, ix, iy) cells of the tree: makes
 * their parents nodes.  The parent of a neighbour is the node's parent, or
 * its neighbour on the node's side: across a side, or with -c a corner.
 * With -k above 1 the neighbours are the block of checkblock.
 */
static void
check(int level, uint64_t ix, uint64_t iy)
{
	int dx = ix & 1 ? 1 : -1, dy = iy & 1 ? 1 : -1;

	if (level == 0)
		return;
	if (opt.k > 1) {
		checkblock(level, ix, iy);
		return;
	}
	need(level - 1, ix >> 1, iy >> 1, dx, 0);
	need(level - 1, ix >> 1, iy >> 1, 0, dy);
	if (opt.corners)
		need(level - 1, ix >> 1, iy >> 1, dx, dy);
}

/*
 * The rate when -k is not given: 1 to level 8, then doubled every second
 * level.  A band K leaves wide at each level puts about K^2 times the
 * levels' count of nodes in the interior, against 2^depth along the
 * boundary; K growing as the square root of 2^depth keeps the two in step,
 * so a deeper tree refines the whole region, not only a thinner band
 * along the rings (on the plate with a hole the stress concentration's
 * error then falls with the level; at rate 1 it grows).
 */
static int
defaultrate(int depth)
{
	int k = 1;

	for (depth -= 7; depth >= 2 && k < MAXRATE; depth -= 2)
		k *= 2;
	return k;
}

/* Checks the nodes made and not yet checked. */
static void
drain(void)
{
	while (work.n > 0) {
		uint64_t iy = work.cell[--work.n];
		uint64_t ix = work.cell[--work.n];

		check((int)(ix >> 56), ix & ((UINT64_C(1) << 56) - 1), iy);
	}
}

/* Checks the input's nodes in preorder, and what each check makes. */
static void
balance(int level, uint64_t ix, uint64_t iy)
{
	unsigned code = cellset_get(t.nodes, level, ix, iy);
	int q;

	check(level, ix, iy);
	drain();
	for (q = 0; q < 4; q++)
		if ((code >> 2 * q & 3) == NODE)
			balance(level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1));
}

/* Writes the subtree of node (level, ix, iy) in preorder. */
static void
writetree(char *path, int level, uint64_t ix, uint64_t iy, int code)
{
	struct cell c;
	unsigned children;
	int q;

	c.path = level > 0 ? path : ".";
	c.level = level;
	c.ix = ix;
	c.iy = iy;
	c.class = classof[code];
	c.text = NULL;
	qt_cell(&c, 0);
	if (code != NODE)
		return;
	children = cellset_get(t.nodes, level, ix, iy);
	for (q = 0; q < 4; q++) {
		path[level] = '0' + q;
		path[level + 1] = '\0';
		writetree(path, level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1),
		    children >> 2 * q & 3);
	}
	path[level] = '\0';
}

/*
 * Reads the tree; the records before its cells, and any of an unknown kind,
 * are written as read.
 */
static void
readtree(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			qt_setuniverse(&rec.u);
			cl.sp = split_new(&rec.u);
			qt_echo(&rec);
			break;
		case QT_RING:
			split_addring(cl.sp, &rec.ring);
			cl.nrings++;
			qt_echo(&rec);
			break;
		case QT_OBJECT:
			cl.combined = 1;
			qt_echo(&rec);
			break;
		case QT_NODE:
		case QT_LEAF:
			if (rec.c.id != 0)
				qt_fail(r, "a numbered leaf: qtbalance takes "
				    "a tree, not qtleaves' elements");
			addcell(r, &rec.c);
			if ((t.ncells & 0xfffff) == 0)
				report(0);
			break;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(r, "the input holds a mesh (%s record): "
			    "qtbalance takes a tree",
			    kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:
			qt_echo(&rec);
			break;
		}
	}
	closeopen(r, 0);
	if (t.ncells == 0)
		qt_fail(r, "no cells: qtbalance takes a tree, as qtsplit "
		    "writes it");
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	char path[QT_MAXLEVEL + 2];
	const char *end;
	long long val;
	int ch;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "ck:vh")) != -1)
		switch (ch) {
		case 'c':
			opt.corners = 1;
			break;
		case 'k':
			if (parselong(optarg, &end, &val) < 0 || *end != '\0' ||
			    val < 1 || val > MAXRATE)
				die(2, "-k: rate must be an integer from 1 to "
				    "%d: %s", MAXRATE, optarg);
			opt.k = val;
			break;
		case 'v':
			opt.verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage(0);

	t.nodes = cellset_new();
	r = qt_openpath(argc == 1 ? argv[0] : "-", QT_NEEDUNIVERSE | QT_ARCS |
	    (opt.verbose ? QT_VERBOSE : 0));
	t.name = qt_name(r);
	qt_header();
	readtree(r);
	if (opt.k == 0)
		opt.k = defaultrate(t.depth);
	if (t.rootclass == 0)
		balance(0, 0, 0);
	report(1);
	path[0] = '\0';
	writetree(path, 0, 0, 0, t.rootclass ? codeof(t.rootclass) : NODE);
	qt_close(r);
	qt_end();
	closeout();
	return 0;
}
