/*
 * qtbool: combine two qtree(5) trees over the same universe, cell by cell,
 * by and, or, minus or xor, into one tree; or, with -q, say by the exit
 * status whether the result has any area.
 *
 * Both trees are walked together in preorder, one pass over each input:
 * the cell the walk is at must be the next cell of each input, unless a
 * leaf above it covers it there, and then that leaf's class is the cell's
 * class in that input.  Where both are leaves, the table of the operation
 * gives the class; where a leaf's class alone decides it (E for and, F for
 * or), the other input's subtree is read and checked, and one leaf
 * written.  The walk goes no deeper than the trees, and holds one cell of
 * each: memory grows with the depth and the heads, not with the cells.
 *
 * The result is condensed: four leaves of one class F or E under a node
 * are that node as a leaf, as qtsplit would have written it.  A node's
 * record must come before its children in preorder, so a node is held
 * until one of its children turns out not to be an F or E leaf like the
 * ones before it; its earlier children, all of that class, are then
 * written after it.  So a held node is its cell, a count and a class: the
 * depth bounds what is held.
 *
 * Two 3D streams (qtree(5), Solids) combine alike, a node's children
 * eight: the walk is the same, only the reader, the writer and the head
 * differ.  A 2D stream and a 3D one do not combine.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

/* -q: what the result holds, as the exit status says it. */
enum { HASAREA = 0, EMPTY = 3, UNDECIDED = 4 };

enum { F, E, P };

/* The class of a cell from its class in each input: table[op][a][b]. */
static const char table[QT_XOR + 1][3][4] = {
	[QT_AND] = { "FEP", "EEE", "PEP" },
	[QT_OR] = { "FFF", "FEP", "FPP" },
	[QT_MINUS] = { "EFP", "EEE", "EPP" },
	[QT_XOR] = { "EFP", "FEP", "PPP" },
};

/* A whole tree read in preorder, a cell at a time. */
struct input {
	const char	*name;
	struct qtreader	*r;
	struct qtrec	 rec;	/* its next cell, QT_EOF after the last */
	enum qtkind	 kind;
	long		 lineno;	/* of the cell taken last */
	/* a 3D stream: its reader, its next cell, its universe */
	struct qt3reader *s;
	struct qt3rec	 rec3;
	struct universe3 u3;
	long		 u3line;
	/* the head: universe, level, and the records to write as read */
	struct qtrec	*universe;
	int		 level;		/* -1 for none */
	struct qtrec	**head;
	size_t		 nhead;
	long		 nobjects;	/* 0: a polygon, one object */
	int		 opterm[2 * QT_MAXOBJECTS];
	int		 nopterm;
};

static struct input in[2];
static int op, quiet;
static int nchild = 4;	/* 8 for two 3D streams */
static unsigned seen;	/* -q: the result's classes, CELL_CLASSBIT bits */

/* decides[side][class]: that class in that input gives the result alone */
static char decides[2][3];

/* The walk's path, and the nodes on it whose record is held or written. */
static char path[QT_MAXLEVEL + 1];

struct opennode {
	uint64_t	 ix, iy, iz;
	int		 written;
	int		 nheld;		/* children held while it is not */
	char		 heldclass;	/* their class, F or E */
};
static struct opennode open[QT_MAXLEVEL + 1];

static void
usage(int help)
{
	usageexit(help, "usage: qtbool [-hq] -o op file1 file2\n");
}

static int
classindex(char c)
{
	return c == 'F' ? F : c == 'E' ? E : P;
}

/* The walk's path down to level, "." for the root. */
static const char *
pathname(int level)
{
	static char buf[QT_MAXLEVEL + 1];

	if (level == 0)
		return ".";
	memcpy(buf, path, level);
	buf[level] = '\0';
	return buf;
}

/*
 * The next record of p that is a cell, into p->rec; other records met
 * among the cells are written as read.
 */
static void
advance3(struct input *p)
{
	while ((p->kind = qt3_read(p->s, &p->rec3)) != QT_EOF &&
	    p->kind != QT_NODE && p->kind != QT_LEAF)
		if (!quiet)	/* the reader refuses head records */
			qt3_echo(&p->rec3);
}

static void
advance(struct input *p)
{
	if (p->s != NULL) {
		advance3(p);
		return;
	}
	for (;;) {
		switch (p->kind = qt_read(p->r, &p->rec)) {
		case QT_EOF:
		case QT_NODE:
		case QT_LEAF:
			return;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(p->r, "the input holds a mesh (%s record): "
			    "qtbool combines trees",
			    p->kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:	/* the reader refuses a head record after cells */
			if (!quiet)
				qt_echo(&p->rec);
			break;
		}
	}
}

/*
 * Takes p's next cell, which must be cell (level, ix, iy, iz) on the
 * walk's path (iz 0 in 2D), and returns its class, 0 for a node.
 */
static char
take(struct input *p, int level, uint64_t ix, uint64_t iy, uint64_t iz)
{
	const struct cell *c = &p->rec.c;
	const struct cell3 *c3 = &p->rec3.c;
	char class;

	if (p->kind == QT_EOF)
		qt_fail(p->r, "not a whole tree: the cells end before cell %s",
		    pathname(level));
	if (p->s != NULL) {
		if (c3->level != level || c3->ix != ix || c3->iy != iy ||
		    c3->iz != iz)
			errat(p->name, p->rec3.lineno, "not a whole tree: cell "
			    "%s where cell %s comes in preorder", c3->path,
			    pathname(level));
		class = c3->class;
		p->lineno = p->rec3.lineno;
	} else {
		if (c->level != level || c->ix != ix || c->iy != iy)
			errat(p->name, p->rec.lineno, "not a whole tree: cell "
			    "%s where cell %s comes in preorder", c->path,
			    pathname(level));
		class = c->class;
		p->lineno = p->rec.lineno;
	}
	advance(p);
	return class;
}

/* Child q's coordinate on axis a (0 x, 1 y, 2 z) from its parent's. */
#define CHILD(v, q, a)	(2 * (v) + ((q) >> (a) & 1))

/* Reads and checks p's subtree under node (level, ix, iy, iz). */
static void
skip(struct input *p, int level, uint64_t ix, uint64_t iy, uint64_t iz)
{
	int q;

	for (q = 0; q < nchild; q++) {
		uint64_t cx = CHILD(ix, q, 0), cy = CHILD(iy, q, 1);
		uint64_t cz = nchild == 8 ? CHILD(iz, q, 2) : 0;

		path[level] = '0' + q;
		if (take(p, level + 1, cx, cy, cz) == 0)
			skip(p, level + 1, cx, cy, cz);
	}
}

static void
writecell3(const char *cellpath, int level, uint64_t ix, uint64_t iy,
    uint64_t iz, char class)
{
	struct cell3 c3;
	char buf[QT_MAXLEVEL + 1];

	memcpy(buf, cellpath, level);	/* qt3_cell takes it as a string */
	buf[level] = '\0';
	memset(&c3, 0, sizeof(c3));
	c3.path = level > 0 ? buf : ".";
	c3.level = level;
	c3.ix = ix;
	c3.iy = iy;
	c3.iz = iz;
	c3.class = class;
	qt3_cell(&in[0].u3, &c3);
}

static inline void
writecell(const char *cellpath, int level, uint64_t ix, uint64_t iy,
    uint64_t iz, char class)
{
	struct cell c;

	if (nchild == 8) {
		writecell3(cellpath, level, ix, iy, iz, class);
		return;
	}
	memset(&c, 0, sizeof(c));
	c.path = level > 0 ? cellpath : ".";
	c.level = level;
	c.ix = ix;
	c.iy = iy;
	c.class = class;
	qt_cell(&c, 0);
}

/*
 * Writes the held nodes down to the one at level, each followed by the
 * children held under it: one of their descendants is not to be condensed.
 */
static void
release(int level)
{
	char buf[QT_MAXLEVEL + 1];
	int top = level, d, q;

	while (top > 0 && !open[top - 1].written)
		top--;
	memcpy(buf, path, level + 1);
	for (d = top; d <= level; d++) {
		struct opennode *o = &open[d];

		writecell(path, d, o->ix, o->iy, o->iz, 0);
		for (q = 0; q < o->nheld; q++) {
			buf[d] = '0' + q;
			writecell(buf, d + 1, CHILD(o->ix, q, 0),
			    CHILD(o->iy, q, 1), nchild == 8 ?
			    CHILD(o->iz, q, 2) : 0, o->heldclass);
		}
		buf[d] = path[d];
		o->written = 1;
	}
}

/* A leaf of the result, on the walk's path. */
static void
putleaf(int level, uint64_t ix, uint64_t iy, uint64_t iz, char class)
{
	struct opennode *o = level > 0 ? &open[level - 1] : NULL;

	if (quiet) {
		seen |= CELL_CLASSBIT(class);
		return;
	}
	if (o != NULL && !o->written) {
		if (class != 'P' && (o->nheld == 0 || class == o->heldclass)) {
			o->heldclass = class;
			if (++o->nheld == nchild)	/* the node is a leaf */
				putleaf(level - 1, o->ix, o->iy, o->iz, class);
			return;
		}
		release(level - 1);
	}
	writecell(path, level, ix, iy, iz, class);
}

/*
 * The cell (level, ix, iy, iz) of the result, and its subtree.  ca and cb
 * are its classes in inputs A and B where a leaf above it covers it, else
 * 0: the input's next cell is this one.
 */
static void
walk(int level, uint64_t ix, uint64_t iy, uint64_t iz, char ca, char cb)
{
	int q;

	if (ca == 0)
		ca = take(&in[0], level, ix, iy, iz);
	if (cb == 0)
		cb = take(&in[1], level, ix, iy, iz);
	if (ca != 0 && cb != 0) {
		putleaf(level, ix, iy, iz,
		    table[op][classindex(ca)][classindex(cb)]);
		return;
	}
	if (ca != 0 && decides[0][classindex(ca)]) {
		skip(&in[1], level, ix, iy, iz);
		putleaf(level, ix, iy, iz, table[op][classindex(ca)][0]);
		return;
	}
	if (cb != 0 && decides[1][classindex(cb)]) {
		skip(&in[0], level, ix, iy, iz);
		putleaf(level, ix, iy, iz, table[op][0][classindex(cb)]);
		return;
	}
	if (!quiet) {
		open[level].ix = ix;
		open[level].iy = iy;
		open[level].iz = iz;
		open[level].written = 0;
		open[level].nheld = 0;
	}
	if (level == QT_MAXLEVEL) {	/* the reader refuses its children */
		struct input *p = &in[ca == 0 ? 0 : 1];

		errat(p->name, p->lineno, "not a whole tree: node %s lies at "
		    "level %d, the deepest, and has no children",
		    pathname(level), QT_MAXLEVEL);
	}
	for (q = 0; q < nchild; q++) {
		path[level] = '0' + q;
		walk(level + 1, CHILD(ix, q, 0), CHILD(iy, q, 1), nchild == 8 ?
		    CHILD(iz, q, 2) : 0, ca, cb);
	}
}

/* Which classes of one input decide the result whatever the other's is. */
static void
setdecides(void)
{
	int a, b;

	for (a = 0; a < 3; a++) {
		const char *row = table[op][a];

		decides[0][a] = row[0] != 'P' && row[0] == row[1] &&
		    row[1] == row[2];
	}
	for (b = 0; b < 3; b++)
		decides[1][b] = table[op][0][b] != 'P' &&
		    table[op][0][b] == table[op][1][b] &&
		    table[op][1][b] == table[op][2][b];
}

static void
keephead(struct input *p, const struct qtrec *rec)
{
	p->head = xreallocarray(p->head, p->nhead + 1, sizeof(*p->head));
	p->head[p->nhead++] = qt_keep(rec);
}

/*
 * A 3D stream's head, as readhead reads a 2D one: its records kept as
 * read, through a qtrec of their text, kind and count.
 */
static void
readhead3(struct input *p)
{
	struct qt3rec *r3 = &p->rec3;
	struct qtrec rec;
	int i;

	p->s = qt3_open(p->r);
	for (;;) {
		switch (p->kind = qt3_read(p->s, r3)) {
		case QT_EOF:
			qt_fail(p->r, "not a whole tree: no cells (qtsplit "
			    "makes a tree of a solid)");
			break;
		case QT_NODE:
		case QT_LEAF:
			return;
		default:
			break;
		}
		memset(&rec, 0, sizeof(rec));
		rec.kind = p->kind;
		rec.line = r3->line;
		rec.len = r3->len;
		rec.lineno = r3->lineno;
		rec.nrec = r3->nrec;
		switch (p->kind) {
		case QT_UNIVERSE:
			p->universe = qt_keep(&rec);
			p->u3 = r3->u;
			break;
		case QT_LEVEL:
			p->level = r3->level;
			break;
		case QT_OP:
			for (i = 0; i < r3->op.n; i++)
				p->opterm[i] = r3->op.term[i];
			p->nopterm = r3->op.n;
			break;
		default:	/* shells, objects, others: written as read */
			if (p->kind == QT_OBJECT)
				p->nobjects = r3->object;
			keephead(p, &rec);
			break;
		}
	}
}

/* Reads p's head, up to its first cell; keeps what is to be written. */
static void
readhead(struct input *p)
{
	int i;

	p->level = -1;
	for (;;) {
		switch (p->kind = qt_read(p->r, &p->rec)) {
		case QT_SOLID:
			readhead3(p);
			return;
		case QT_EOF:
			qt_fail(p->r, "not a whole tree: no cells (qtsplit "
			    "makes a tree of a polygon)");
			break;
		case QT_NODE:
		case QT_LEAF:
			return;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(p->r, "the input holds a mesh (%s record): "
			    "qtbool combines trees",
			    p->kind == QT_ELEM ? "elem" : "vertex");
			break;
		case QT_UNIVERSE:
			p->universe = qt_keep(&p->rec);
			p->universe->u = p->rec.u;
			break;
		case QT_LEVEL:
			p->level = p->rec.level;
			break;
		case QT_OP:
			for (i = 0; i < p->rec.op.n; i++)
				p->opterm[i] = p->rec.op.term[i];
			p->nopterm = p->rec.op.n;
			break;
		default:	/* rings, objects, others: written as read */
			if (p->rec.kind == QT_OBJECT)
				p->nobjects = p->rec.object;
			keephead(p, &p->rec);
			break;
		}
	}
}

/*
 * The head of the result: the universe, the deeper level, the objects of
 * A and then B's, renumbered after A's, and the op record over them.
 */
static void
writehead(void)
{
	struct qtop expr;
	int term[2 * QT_MAXOBJECTS], n = 0, i, j;
	long first = 1, k;

	if (nchild == 8) {
		qt3_header();
		qt3_universe(&in[0].u3);
	} else {
		qt_header();
		qt_universe(&in[0].universe->u);
	}
	if (in[0].level >= 0 || in[1].level >= 0)
		qt_level(in[0].level > in[1].level ? in[0].level :
		    in[1].level);
	term[n++] = -op;
	for (i = 0; i < 2; i++) {
		struct input *p = &in[i];

		if (p->nobjects == 0)
			qt_object(first);
		for (k = first, j = 0; j < (int)p->nhead; j++)
			if (p->head[j]->kind == QT_OBJECT)
				qt_object(k++);
			else
				qt_echo(p->head[j]);
		if (p->nobjects == 0)
			term[n++] = (int)first;
		for (j = 0; j < p->nopterm; j++)
			term[n++] = p->opterm[j] > 0 ?
			    p->opterm[j] + (int)first - 1 : p->opterm[j];
		first += p->nobjects > 0 ? p->nobjects : 1;
	}
	expr.n = n;
	expr.term = term;
	qt_op(&expr);
}

/*
 * The streams must be of one dimension, the universes the same doubles,
 * the objects few enough.
 */
static void
samehead(void)
{
	const struct qtrec *a = in[0].universe, *b = in[1].universe;
	long na = in[0].nobjects ? in[0].nobjects : 1;
	long nb = in[1].nobjects ? in[1].nobjects : 1;

	if ((in[0].s == NULL) != (in[1].s == NULL))
		errat(in[1].name, 1, "a %s stream, and %s is a %s one: qtbool "
		    "combines two trees of one dimension", in[1].s ? "3D" :
		    "2D", in[0].name, in[0].s ? "3D" : "2D");
	if (in[0].s != NULL ? in[0].u3.x0 != in[1].u3.x0 ||
	    in[0].u3.y0 != in[1].u3.y0 || in[0].u3.z0 != in[1].u3.z0 ||
	    in[0].u3.size != in[1].u3.size : a->u.x0 != b->u.x0 ||
	    a->u.y0 != b->u.y0 || a->u.size != b->u.size)
		errat(in[1].name, b->lineno, "another universe: %.*s, where "
		    "%s:%ld has %.*s", (int)b->len, b->line, in[0].name,
		    a->lineno, (int)a->len, a->line);
	if (na + nb > QT_MAXOBJECTS)
		errat(in[1].name, 0, "%ld object%s here and %ld in %s: more "
		    "than %d in one stream", nb, nb > 1 ? "s" : "", na,
		    in[0].name, QT_MAXOBJECTS);
}

int
main(int argc, char *argv[])
{
	FILE *fp;
	int ch, i;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "o:qh")) != -1)
		switch (ch) {
		case 'o':
			if ((op = op_code(optarg)) == 0)
				die(2, "-o: unknown operation %s (and, or, "
				    "minus, xor)", optarg);
			break;
		case 'q':
			quiet = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc != 2 || op == 0)
		usage(0);
	if (strcmp(argv[0], "-") == 0 && strcmp(argv[1], "-") == 0)
		die(2, "the standard input (-) named twice");
	setdecides();

	for (i = 0; i < 2; i++) {
		fp = openin(argv[i], &in[i].name);
		in[i].r = qt_open(fp, in[i].name,
		    QT_NEEDUNIVERSE | QT_ARCS | QT_SOLIDS);
		readhead(&in[i]);
	}
	samehead();
	if (in[0].s != NULL)
		nchild = 8;
	if (!quiet) {
		if (nchild == 4)
			qt_setuniverse(&in[0].universe->u);
		writehead();
	}
	/* a whole tree read, the reader has seen its stream to the end */
	walk(0, 0, 0, 0, 0, 0);
	for (i = 0; i < 2; i++) {
		qt3_close(in[i].s);
		qt_close(in[i].r);
	}
	if (quiet)
		return seen & CELL_CLASSBIT('F') ? HASAREA :
		    seen & CELL_CLASSBIT('P') ? UNDECIDED : EMPTY;
	qt_end();
	closeout();
	return 0;
}
