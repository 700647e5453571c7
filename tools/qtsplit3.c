/*
 * qtsplit on a 3D stream: the octree of a solid, by lib/split3.c, written
 * in preorder as qtsplit.c writes the quadtree, with the same options.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtsplit.h"

static struct {
	struct universe3 u;
	int		 level;		/* the level record's, -1 for none */
	struct splitter3 *sp;
	struct qt3rec	**keep;		/* shells and other records */
	char		**text;
	size_t		 nkeep;
} in3 = { .level = -1 };

static struct {
	const struct split3opts *o;
	int		 deepest;	/* the deepest level a cell may reach */
	char		 path[QT_MAXLEVEL + 2];
	unsigned long long ncells;
	int		 deepestseen;
} w3;

static void
keeprec(const struct qt3rec *rec)
{
	struct qt3rec *k = xmalloc(sizeof(*k));
	char *t = xmalloc(rec->len + 1);

	memcpy(t, rec->line, rec->len);
	t[rec->len] = '\0';
	*k = *rec;
	k->line = t;
	in3.keep = xreallocarray(in3.keep, in3.nkeep + 1, sizeof(*in3.keep));
	in3.keep[in3.nkeep++] = k;
}

static void
readsolid(struct qtreader *r)
{
	struct qt3reader *s = qt3_open(r);
	struct qt3rec rec;
	int haveu = 0;

	while (qt3_read(s, &rec) != QT_EOF)
		switch (rec.kind) {
		case QT_UNIVERSE:
			in3.u = rec.u;
			in3.sp = split3_new(&in3.u);
			haveu = 1;
			break;
		case QT_LEVEL:
			in3.level = rec.level;
			break;
		case QT_SHELL:
			split3_addshell(in3.sp, &rec.shell);
			keeprec(&rec);
			break;
		case QT_NODE:
		case QT_LEAF:
			qt_fail(r, "the input already holds cells: qtsplit "
			    "takes shells");
			break;
		case QT_OBJECT:
			qt_fail(r, "the input combines objects (object record, "
			    "from qtbool): qtsplit decomposes one solid; "
			    "split each and combine the trees");
			break;
		default:
			keeprec(&rec);
			break;
		}
	if (!haveu)
		qt_fail(r, "no universe record");
	qt3_close(s);
}

static void
emit3(int level, uint64_t ix, uint64_t iy, uint64_t iz, char class)
{
	struct cell3 c;

	if (w3.o->cutopt == 's')
		return;
	c.path = level > 0 ? w3.path : ".";
	c.level = level;
	c.ix = ix, c.iy = iy, c.iz = iz;
	c.class = class;
	c.id = 0;
	qt3_cell(&in3.u, &c);
	if (level > w3.deepestseen)
		w3.deepestseen = level;
	if ((++w3.ncells & 0xfffff) == 0 && w3.o->verbose)
		progress(0, "%llu cells, deepest level %d", w3.ncells,
		    w3.deepestseen);
}

static int
splits3(int level, size_t n)
{
	if (level < w3.o->minlevel)
		return 1;
	return n > 0 && level < w3.deepest;
}

static void
visit3(int level, uint64_t ix, uint64_t iy, uint64_t iz, size_t n,
    int inside)
{
	unsigned occupied = 0;
	int parity[8], q, leaves;

	if (!splits3(level, n)) {
		emit3(level, ix, iy, iz, split_class(n, inside));
		return;
	}
	emit3(level, ix, iy, iz, 0);
	if (level == w3.o->cut) {
		if (w3.o->cutopt == 's' && printf("%s\n", level > 0 ?
		    w3.path : ".") < 0)
			die(1, "write error");
		return;
	}
	/* the children are leaves: whether they have triangles is enough */
	leaves = !splits3(level + 1, 1);
	if (n > 0)
		occupied = split3_children(in3.sp, level, ix, iy, iz, n, inside,
		    leaves, parity);
	else
		for (q = 0; q < 8; q++)
			parity[q] = inside;
	for (q = 0; q < 8; q++) {
		size_t m = n == 0 ? 0 : leaves ? occupied >> q & 1 :
		    split3_child(in3.sp, level, n, q);

		w3.path[level] = '0' + q;
		w3.path[level + 1] = '\0';
		visit3(level + 1, 2 * ix + (q & 1), 2 * iy + (q >> 1 & 1),
		    2 * iz + (q >> 2), m, parity[q]);
	}
	w3.path[level] = '\0';
}

/* Down to -r's cell as visit3 would go, its triangles and parity kept. */
static int
descend3(const char *subtree, uint64_t *ix, uint64_t *iy, uint64_t *iz,
    size_t *n, int *inside)
{
	int depth = strlen(subtree), i;

	if (strcmp(subtree, ".") == 0)
		return 0;
	if (depth > QT_MAXLEVEL || pathcell3(subtree, depth, ix, iy, iz) < 0)
		die(2, "-r: not a cell path of a 3D stream: %s", subtree);
	for (i = 0; i < depth; i++) {
		int parity[8], q = subtree[i] - '0';

		if (!splits3(i, *n))
			die(1, "-r: no cell %s in the tree: cell %.*s is a leaf",
			    subtree, i > 0 ? i : 1, i > 0 ? subtree : ".");
		if (*n > 0)
			split3_children(in3.sp, i, *ix >> (depth - i),
			    *iy >> (depth - i), *iz >> (depth - i), *n,
			    *inside, 0, parity);
		else
			parity[q] = *inside;
		*n = *n > 0 ? split3_child(in3.sp, i, *n, q) : 0;
		*inside = parity[q];
		w3.path[i] = subtree[i];
	}
	w3.path[depth] = '\0';
	return depth;
}

int
split3main(struct qtreader *r, const struct split3opts *o)
{
	uint64_t ix = 0, iy = 0, iz = 0;
	size_t n, i;
	int inside, level, deepest, maxlevel = o->maxlevel;
	const char *msg;

	w3.o = o;
	if (o->nrl > 0)
		die(2, "-L: a 3D stream has shells, not rings");
	readsolid(r);
	qt_close(r);
	deepest = univ3deepest(&in3.u);
	if (maxlevel < 0)
		maxlevel = in3.level >= 0 ? in3.level : deepest < 6 ?
		    deepest : 6;
	if ((msg = univ3check(&in3.u, maxlevel)) != NULL)
		die(2, "-l: %s", msg);
	if (o->minlevel > maxlevel)
		die(2, "-m %d is deeper than the maximum level %d",
		    o->minlevel, maxlevel);
	w3.deepest = maxlevel;
	if (o->cutopt != 's') {
		qt3_header();
		qt3_universe(&in3.u);
		qt_level(maxlevel);
		for (i = 0; i < in3.nkeep; i++)
			qt3_echo(in3.keep[i]);
	}
	n = split3_root(in3.sp, &inside);
	level = descend3(o->subtree, &ix, &iy, &iz, &n, &inside);
	if (o->cutopt != 0 && o->cut < level)
		die(2, "-%c %d is above the cell %s", o->cutopt, o->cut,
		    o->subtree);
	visit3(level, ix, iy, iz, n, inside);
	if (o->cutopt != 's')
		qt_end();
	if (o->verbose)
		progress(1, "%llu cells, %llu bytes, deepest level %d",
		    w3.ncells, qt_bytes(), w3.deepestseen);
	for (i = 0; i < in3.nkeep; i++) {
		free((char *)in3.keep[i]->line);
		free(in3.keep[i]);
	}
	free(in3.keep);
	split3_free(in3.sp);
	closeout();
	return 0;
}
