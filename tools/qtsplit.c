/*
 * qtsplit: decompose the region of a qtree(5) stream into a quadtree.
 *
 * The classifier is the library's (lib/split.c): each cell gets the edges
 * of its parent that meet it, and a cell without edges the even-odd parity
 * carried from its parent.  This file walks the tree in preorder and writes
 * it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

/* What the options ask for; maxlevel is -1 until the stream is read. */
static struct options {
	int	minlevel, maxlevel;
	int	verbose;
} opt = { .maxlevel = -1 };

/*
 * The stream: its universe, its rings (as edges, in the splitter), and its
 * records to write as read, rings first.
 */
static struct input {
	struct universe	 u;
	int		 level;		/* of its level record; -1 for none */
	struct splitter	*sp;
	struct qtrec	**rings, **others;
	size_t		 nrings, nothers;
} in = { .level = -1 };

/* The walk down the tree, in preorder, and what it has written. */
static struct walk {
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

static int
splits(int level, size_t n)
{
	return level < opt.minlevel || (n > 0 && level < opt.maxlevel);
}

/* Writes the cell and its subtree; its n edges are the splitter's at level. */
static void
visit(int level, uint64_t ix, uint64_t iy, size_t n, int inside)
{
	int parity[4], q;

	if (!splits(level, n)) {
		emit(level, ix, iy, split_class(n, inside));
		return;
	}
	emit(level, ix, iy, 0);
	if (n > 0)
		split_children(in.sp, level, ix, iy, n, inside, parity);
	else
		parity[0] = parity[1] = parity[2] = parity[3] = inside;
	for (q = 0; q < 4; q++) {
		size_t m = n > 0 ? split_child(in.sp, level, n, q) : 0;

		walk.path[level] = '0' + q;
		walk.path[level + 1] = '\0';
		visit(level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1), m,
		    parity[q]);
	}
	walk.path[level] = '\0';
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
			in.sp = split_new(&in.u);
			break;
		case QT_LEVEL:
			in.level = rec.level;
			break;
		case QT_RING:
			split_addring(in.sp, &rec.ring);
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
			split_children(in.sp, i, *ix >> (depth - i),
			    *iy >> (depth - i), *n, *inside, parity);
		else
			parity[q] = *inside;
		*n = *n > 0 ? split_child(in.sp, i, *n, q) : 0;
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
	int ch, inside, level;

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
	writehead();
	n = split_root(in.sp, &inside);
	level = descend(subtree, &ix, &iy, &n, &inside);
	visit(level, ix, iy, n, inside);
	qt_end();
	report(1);
	closeout();
	return 0;
}
