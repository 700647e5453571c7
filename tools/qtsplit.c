/*
 * qtsplit: decompose the region of a qtree(5) stream into a quadtree.
 *
 * The classifier is the library's (lib/split.c): each cell gets the edges
 * of its parent that meet it, and a cell without edges the even-odd parity
 * carried from its parent.  This file walks the tree in preorder and writes
 * it.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtsplit.h"

/* One -L: ring id's level, or every hole's for id 0. */
struct ringlevel {
	long	id;
	int	level;
};

/*
 * What the options ask for; maxlevel is -1 until the stream is read, and
 * deepest is the level record's: the deepest level a cell may be split to.
 * A cut (-s, -t) at level cut: the tree above it with its nodes there
 * (-t), or their paths alone (-s), the roots of the shards below.
 */
static struct options {
	int	minlevel, maxlevel, deepest;
	int	verbose;
	int	cut, cutopt;
	struct ringlevel *rl;	/* -L, in the order given */
	size_t	 nrl;
	const char **roots;	/* -r, in the order given */
	size_t	 nroots;
	const char *out;	/* -o: a file a root, its name's pattern */
} opt = { .maxlevel = -1, .cut = -1 };

/*
 * The stream: its universe, its rings (as edges, in the splitter), and its
 * records to write as read, rings first.
 */
static struct input {
	struct universe	 u;
	int		 level;		/* of its level record; -1 for none */
	struct splitter	*sp;
	struct qtrec	**rings, **others;
	unsigned char	*hole;		/* per ring: a hole */
	size_t		 nrings, nothers;
} in = { .level = -1 };

/*
 * For -v, before the walk: the cells of the tree down to level limit (to
 * CENSUSLEVEL, or 8 levels below -r's cell), counted by the same walk
 * without output.
 */
#define CENSUSLEVEL	12

static struct census {
	int		 on, limit;
	unsigned long long cells[QT_MAXLEVEL + 1], partial[QT_MAXLEVEL + 1];
} census;

/* The walk down the tree, in preorder, and what it has written. */
static struct walk {
	char		 path[QT_MAXLEVEL + 2];	/* of the cell at hand */
	int		 root;		/* the level of -r's cell */
	unsigned long long ncells;
	int		 deepest;
} walk;

static void
usage(int help)
{
	usageexit(help, "usage: qtsplit [-hv] [-L ring=level] [-l level] "
	    "[-m level] [-o pattern] [-r path ...] [-s level | -t level] "
	    "[file]\n");
}

static void
keep(struct qtrec ***list, size_t *n, const struct qtrec *rec)
{
	*list = xreallocarray(*list, *n + 1, sizeof(**list));
	(*list)[(*n)++] = qt_keep(rec);
}

/*
 * Progress for -v: cells so far and the share of the tree's square that
 * preorder has passed, the place of the cell at hand in Z order.
 */
static void
report(int force)
{
	double swept = 0, share = 1;
	int i;

	if (!opt.verbose)
		return;
	if (force) {
		progress(1, "%llu cells, %llu bytes, deepest level %d",
		    walk.ncells, qt_bytes(), walk.deepest);
		return;
	}
	for (i = walk.root; walk.path[i] != '\0'; i++) {
		share /= 4;
		swept += (walk.path[i] - '0') * share;
	}
	progress(0, "%llu cells, deepest level %d, %.1f%% of the %s swept",
	    walk.ncells, walk.deepest, 100 * swept,
	    walk.root > 0 ? "subtree" : "universe");
}

/* Writes a cell; class 0 for a node. */
static void
emit(int level, uint64_t ix, uint64_t iy, char class)
{
	struct cell c;

	if (opt.cutopt == 's')
		return;
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
 * A cell of n edges is split above the minimum level, and when partial
 * while some ring that meets it allows the next level.
 */
static inline int
splits(int level, size_t n)
{
	if (level < opt.minlevel)
		return 1;
	if (n == 0 || level >= opt.deepest)
		return 0;
	return opt.nrl == 0 || split_allows(in.sp, level, n);
}

/* A node at the cut: -s lists its path, -t has written it. */
static void
shardroot(int level)
{
	if (opt.cutopt == 's' && printf("%s\n", level > 0 ? walk.path : ".") < 0)
		die(1, "write error");
}

/* Writes the cell and its subtree; its n edges are the splitter's at level. */
static void
visit(int level, uint64_t ix, uint64_t iy, size_t n, int inside)
{
	int parity[4], q;

	if (census.on) {
		census.cells[level]++;
		census.partial[level] += n > 0;
		if (level == census.limit || !splits(level, n))
			return;
	} else if (!splits(level, n)) {
		emit(level, ix, iy, split_class(n, inside));
		return;
	} else
		emit(level, ix, iy, 0);
	if (level == opt.cut && !census.on) {
		shardroot(level);
		return;
	}
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
static int
readrings(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_SOLID:
			return 1;	/* a 3D stream: qtsplit3.c reads it */
		case QT_UNIVERSE:
			in.u = rec.u;
			in.sp = split_new(&in.u);
			break;
		case QT_LEVEL:
			in.level = rec.level;
			break;
		case QT_RING:
			split_addring(in.sp, &rec.ring);
			in.hole = xreallocarray(in.hole, in.nrings + 1, 1);
			in.hole[in.nrings] = rec.ring.hole;
			keep(&in.rings, &in.nrings, &rec);
			break;
		case QT_NODE:
		case QT_LEAF:
			qt_fail(r, "the input already holds cells: qtsplit "
			    "takes rings");
			break;
		case QT_OBJECT:
			qt_fail(r, "the input combines objects (object record, "
			    "from qtbool): qtsplit decomposes one polygon; "
			    "split each and combine the trees");
			break;
		default:
			keep(&in.others, &in.nothers, &rec);
			break;
		}
	}
	return 0;
}

/* -L RING=LEVEL: RING a ring's id or "holes". */
static void
addringlevel(const char *arg)
{
	const char *eq = strchr(arg, '='), *end;
	long long id = 0, level;
	struct ringlevel *rl;

	if (eq == NULL)
		die(2, "-L: not RING=LEVEL: %s", arg);
	if (!(eq - arg == 5 && strncmp(arg, "holes", 5) == 0) &&
	    (parselong(arg, &end, &id) < 0 || end != eq || id < 1))
		die(2, "-L: a ring is a positive ring id or holes: %s", arg);
	if (parselong(eq + 1, &end, &level) < 0 || *end != '\0' ||
	    level < 0 || level > QT_MAXLEVEL)
		die(2, "-L: level must be an integer from 0 to %d: %s",
		    QT_MAXLEVEL, arg);
	opt.rl = xreallocarray(opt.rl, opt.nrl + 1, sizeof(*opt.rl));
	rl = &opt.rl[opt.nrl++];
	rl->id = id;
	rl->level = level;
}

/*
 * The maximum level: -l's, the level record's, else 6 or the universe's
 * deepest level when that is less.  No level an option asks for may be
 * past it (the reader has checked the level record's).
 */
static void
checklevels(void)
{
	int deepest = cell_univdeepest(&in.u, NULL, 0);
	size_t j;

	if (opt.maxlevel < 0)
		opt.maxlevel = in.level >= 0 ? in.level :
		    deepest < 6 ? deepest : 6;
	if (opt.maxlevel > deepest)
		die(2, "-l: %s", cell_univcheck(&in.u, opt.maxlevel));
	for (j = 0; j < opt.nrl; j++)
		if (opt.rl[j].level > deepest)
			die(2, "-L: %s", cell_univcheck(&in.u, opt.rl[j].level));
}

/*
 * Gives each ring its level, -l's or the last -L's that names it, and
 * sets the deepest level a cell may be split to.
 */
static void
ringlevels(void)
{
	size_t i, j;

	opt.deepest = opt.maxlevel;
	for (j = 0; j < opt.nrl; j++)
		if (opt.rl[j].id > (long)in.nrings)
			die(2, "-L: no ring %ld: the stream has %zu",
			    opt.rl[j].id, in.nrings);
	if (opt.nrl > 0 && in.nrings > 0) {
		opt.deepest = 0;
		for (i = 0; i < in.nrings; i++) {
			int level = opt.maxlevel;

			for (j = 0; j < opt.nrl; j++)
				if (opt.rl[j].id == (long)i + 1 ||
				    (opt.rl[j].id == 0 && in.hole[i]))
					level = opt.rl[j].level;
			split_ringlevel(in.sp, i, level);
			if (level > opt.deepest)
				opt.deepest = level;
		}
	}
	if (opt.minlevel > opt.deepest)
		opt.deepest = opt.minlevel;
}

/* The head, the same in every stream written (-o writes several). */
static void
writehead(void)
{
	size_t i;

	qt_header();
	qt_universe(&in.u);
	qt_level(opt.deepest);
	for (i = 0; i < in.nrings; i++)
		qt_echo(in.rings[i]);
	for (i = 0; i < in.nothers; i++)
		qt_echo(in.others[i]);
}

/*
 * The last walk down to a root of -r: the cells on the way, their edges'
 * numbers and parities.  A cell's edges stay in the splitter's list of
 * its level while the subtrees below it are walked, so the next root's
 * walk starts where its path parts from this one.
 */
static struct {
	char	 path[QT_MAXLEVEL + 1];
	size_t	 n[QT_MAXLEVEL + 1];
	int	 inside[QT_MAXLEVEL + 1];
	int	 depth;		/* -1: none yet */
} down = { .depth = -1 };

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
		depth = 0;
	if (depth > QT_MAXLEVEL ||
	    (depth > 0 && cell_frompath(subtree, depth, ix, iy) < 0))
		die(2, "-r: not a cell path: %s", subtree);
	if (down.depth < 0) {
		down.n[0] = split_root(in.sp, &down.inside[0]);
		down.depth = 0;
	}
	for (i = 0; i < depth && i < down.depth && subtree[i] == down.path[i];
	    i++)
		;
	*n = down.n[i];
	*inside = down.inside[i];
	memcpy(walk.path, subtree, i);
	for (; i < depth; i++) {
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
		walk.path[i] = down.path[i] = subtree[i];
		down.n[i + 1] = *n;
		down.inside[i + 1] = *inside;
	}
	walk.path[depth] = '\0';
	down.depth = depth;
	return depth;
}

/*
 * The size of the output foretold for -v: the tree is counted down a
 * few levels, and below them the partial cells, which alone are split,
 * grow level by level as they did from the level above it (twice as many
 * a level along a smooth boundary, so the output doubles with each level
 * and grows with the boundary's length).  A cell takes about 68 bytes and
 * 1.6 more a level (its path and its column and row numbers grow).
 */
static void
foretell(int level, uint64_t ix, uint64_t iy, size_t n, int inside)
{
	double cells = 0, bytes = 0, partial, split, growth = 2;
	int k, last = level + 8 > CENSUSLEVEL ? level + 8 : CENSUSLEVEL;

	if (last > opt.deepest)
		last = opt.deepest;
	memset(census.cells, 0, sizeof(census.cells));
	memset(census.partial, 0, sizeof(census.partial));
	census.on = 1;
	census.limit = last;
	visit(level, ix, iy, n, inside);
	census.on = 0;
	for (k = level; k <= last; k++) {
		cells += census.cells[k];
		bytes += census.cells[k] * (68 + 1.6 * k);
	}
	partial = census.partial[last];
	if (last > level && census.partial[last - 1] > 0 && partial > 0)
		growth = partial / census.partial[last - 1];
	/* below the minimum level every cell splits, not only partial ones */
	split = last < opt.minlevel ? census.cells[last] : partial;
	for (k = last + 1; k <= opt.deepest; k++) {
		cells += 4 * split;
		bytes += 4 * split * (68 + 1.6 * k);
		split = k < opt.minlevel ? 4 * split : partial * growth;
		partial *= growth;
	}
	if (last == opt.deepest)
		progress(1, "%.0f cells, about %.2g bytes, to come", cells,
		    bytes);
	else
		progress(1, "about %.2g cells, %.2g bytes, to come (counted to "
		    "level %d; partial cells then grow %.2gx a level)", cells,
		    bytes, last, growth);
}

/*
 * -r's roots: cell paths in preorder, none inside another, so that their
 * subtrees, one after another, come in preorder too.
 */
static void
checkroots(void)
{
	struct cell a, b;
	size_t k;
	int la, lb;

	for (k = 0; k < opt.nroots; k++) {
		const char *p = opt.roots[k];

		lb = strcmp(p, ".") == 0 ? 0 : (int)strlen(p);
		if (lb > QT_MAXLEVEL ||
		    (lb > 0 && cell_frompath(p, lb, &b.ix, &b.iy) < 0))
			die(2, "-r: not a cell path: %s", p);
		if (lb == 0)
			b.ix = b.iy = 0;
		b.level = lb;
		if (k > 0 && (cell_cmp(&a, &b) >= 0 || (lb >= la &&
		    b.ix >> (lb - la) == a.ix && b.iy >> (lb - la) == a.iy)))
			die(2, "-r: %s %s %s: give the roots in preorder, "
			    "none inside another", p, cell_cmp(&a, &b) >= 0 ?
			    "comes before" : "lies inside", opt.roots[k - 1]);
		a = b;
		la = lb;
	}
}

/*
 * -o: the file of the root at path, its name the pattern with %s the
 * path and %% a %; the standard output is reopened on it.
 */
static void
openshard(const char *path)
{
	static char *name;
	static size_t cap;
	const char *p;
	size_t n = 0, len;

	for (p = opt.out; *p != '\0'; p++) {
		const char *s = p;

		len = 1;
		if (*p == '%') {
			s = *++p == 's' ? path : p;
			len = *p == 's' ? strlen(path) : 1;
		}
		name = xgrow(name, &cap, n + len + 1, 1);
		memcpy(name + n, s, len);
		n += len;
	}
	name[n] = '\0';
	if (fflush(stdout) == EOF || ferror(stdout))
		die(1, "write error: %s", strerror(errno ? errno : EIO));
	if (freopen(name, "w", stdout) == NULL)
		die(1, "%s: %s", name, strerror(errno));
}

/* -o's pattern: %s for the root's path, %% for a %, no other %. */
static void
checkpattern(const char *pat)
{
	const char *p;
	int paths = 0;

	for (p = pat; *p != '\0'; p++)
		if (*p == '%') {
			p++;
			if (*p != 's' && *p != '%')
				die(2, "-o: %%%c: the pattern takes %%s (the "
				    "root's path) and %%%% alone: %s",
				    *p != '\0' ? *p : ' ', pat);
			paths += *p == 's';
		}
	if (paths == 0)
		die(2, "-o: no %%s in the pattern, so every root's file "
		    "would be the same: %s", pat);
}

/* The subtree under the cell at path, written or listed as asked. */
static void
splitroot(const char *path)
{
	uint64_t ix = 0, iy = 0;
	size_t n;
	int inside, level;

	level = descend(path, &ix, &iy, &n, &inside);
	walk.root = level;
	if (opt.cutopt != 0 && opt.cut < level)
		die(2, "-%c %d is above the cell %s", opt.cutopt, opt.cut,
		    path);
	if (opt.verbose && opt.cutopt == 0)
		foretell(level, ix, iy, n, inside);
	visit(level, ix, iy, n, inside);
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	const char *end;
	long long val;
	size_t k;
	int ch;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "L:l:m:o:r:s:t:vh")) != -1)
		switch (ch) {
		case 'L':
			addringlevel(optarg);
			break;
		case 'l':
		case 'm':
		case 's':
		case 't':
			if (parselong(optarg, &end, &val) < 0 || *end != '\0' ||
			    val < 0 || val > QT_MAXLEVEL)
				die(2, "-%c: level must be an integer from 0 "
				    "to %d: %s", ch, QT_MAXLEVEL, optarg);
			if (ch == 'l')
				opt.maxlevel = val;
			else if (ch == 'm')
				opt.minlevel = val;
			else if (opt.cutopt != 0 && opt.cutopt != ch)
				usage(0);
			else {
				opt.cut = val;
				opt.cutopt = ch;
			}
			break;
		case 'o':
			checkpattern(optarg);
			opt.out = optarg;
			break;
		case 'r':
			opt.roots = xreallocarray(opt.roots, opt.nroots + 1,
			    sizeof(*opt.roots));
			opt.roots[opt.nroots++] = optarg;
			break;
		case 'v':
			opt.verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc > 1 || (opt.out != NULL && opt.cutopt == 's'))
		usage(0);
	if (opt.nroots == 0) {
		static const char *whole[] = { "." };

		opt.roots = whole;
		opt.nroots = 1;
	}
	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_NEEDUNIVERSE | QT_ARCS | QT_SOLIDS);
	if (readrings(r)) {
		struct split3opts o = { opt.minlevel, opt.maxlevel, opt.cut,
		    opt.cutopt, opt.roots[0], opt.verbose, opt.nrl };

		if (opt.out != NULL)
			die(2, "-o: 2D streams only");
		if (opt.nroots > 1)
			die(2, "-r: one root alone in a 3D stream");
		return split3main(r, &o);
	}
	qt_close(r);
	checkroots();
	checklevels();
	if (opt.minlevel > opt.maxlevel)
		die(2, "-m %d is deeper than the maximum level %d",
		    opt.minlevel, opt.maxlevel);
	ringlevels();
	if (opt.cutopt != 's' && opt.out == NULL)
		writehead();
	for (k = 0; k < opt.nroots; k++) {
		if (opt.out != NULL) {
			openshard(opt.roots[k]);
			writehead();
		}
		splitroot(opt.roots[k]);
		if (opt.out != NULL)
			qt_end();
	}
	if (opt.cutopt != 's' && opt.out == NULL)
		qt_end();
	report(1);
	closeout();
	return 0;
}
