/*
 * qtcat: join qtree(5) streams of one polygon into one stream, cells in
 * preorder: the shards of a tree made apart (qtsplit -r) back into the
 * tree, or, with -u, what is left of streams after lines were removed or
 * reordered, sealed again.
 *
 * Every input's head, the records before its first cell, must be the first
 * input's, line for line; it is written once, as read.  Without -u the
 * inputs are sealed streams, each in preorder, so a k-way merge by cell
 * order (a heap of the inputs by their current cell) writes the union in
 * preorder as it reads, holding one cell an input; the cells must then
 * make one whole tree, which the merge checks cell by cell: each is the
 * one that preorder puts after the last.  With -u the cells are held,
 * sorted and written: any order, any subset.  Either way a cell comes once,
 * except a node, which shards may share.
 *
 * A shard in a file is copied whole, not read cell by cell: when its head
 * is the first input's byte for byte and its first and last cells say it
 * is one whole subtree, its cells go out as its bytes, in large reads, at
 * the place of its first cell, unless another input has a cell among
 * them; the lines copied must be the cells its end record counts.
 *
 * 3D streams (octrees) join alike, read by read3.c and given to the merge
 * as 2D records: their cells in the order of their paths, eight children
 * a node.  All inputs are of one dimension.
 */
#include <sys/stat.h>

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtcat.h"

/* A cell held under -u: what qt_cell needs, and where it was read. */
struct heldcell {
	uint64_t	 ix, iy;
	unsigned long long id;
	double		 frac;
	long		 lineno;
	int		 input;
	unsigned char	 level;
	char		 class;
};

static struct input *in;
static int nin, unsealed, checkall;

int dim;
static const char *dimname;	/* the input that said it */
char lastdigit = '3';
static struct universe3 u3;	/* a 3D stream's, to write its cells */

char *headtext;
size_t headlen;
unsigned long long headrecs;
long headlines;
char *chunk;

/* The first head read, to compare and write, and its input's name. */
static struct qtrec **head;
static size_t nhead, headcap;
static const char *headname;

/* The last cell written, and the first: the tree's root. */
struct written {
	char		 path[QT_MAXLEVEL + 1];
	int		 level;
	char		 class;
	const char	*name;
	long		 lineno;
	int		 have;
};
static struct written last, root;

static struct heldcell *held;
static size_t nheld, heldcap;

static void
usage(int help)
{
	usageexit(help, "usage: qtcat [-chu] [file ...]\n");
}

static const char *
pathname(const char *path, int level)
{
	return level > 0 ? path : ".";
}

/* The path of cell (level, ix, iy) into path, "." for the root. */
static const char *
cellpath(char *path, int level, uint64_t ix, uint64_t iy)
{
	int k;

	for (k = 0; k < level; k++) {
		int b = level - 1 - k;

		path[k] = '0' + (int)((ix >> b & 1) | (iy >> b & 1) << 1);
	}
	path[level] = '\0';
	return pathname(path, level);
}

/* The word that names a record of the head in messages. */
static const char *
recword(const struct qtrec *rec, char *buf, size_t size)
{
	size_t n;

	switch (rec->kind) {
	case QT_UNIVERSE:
		return "universe";
	case QT_LEVEL:
		return "level";
	case QT_RING:
		return "ring";
	default:
		n = strcspn(rec->line, " ");
		snprintf(buf, size, "%.*s", (int)(n < 40 ? n : 40), rec->line);
		return buf;
	}
}

/*
 * Refuses the head record rec of input p (NULL where p's head ends, at
 * its first cell or the end of its input, line) unless it is the first
 * input's j-th record, byte for byte.
 */
static void
samehead(const struct input *p, size_t j, const struct qtrec *rec, long line)
{
	const struct qtrec *h = j < nhead ? head[j] : NULL;
	const char *a, *b;
	char wa[48], wb[48];
	long la, lb;
	size_t k;

	if (rec != NULL && h != NULL && h->len == rec->len &&
	    memcmp(h->line, rec->line, rec->len) == 0)
		return;
	if (rec == NULL && h == NULL)
		return;
	if (rec == NULL)
		errat(p->name, line, "another polygon: the head ends here, "
		    "where %s:%ld has a %s record", headname, h->lineno,
		    recword(h, wa, sizeof(wa)));
	if (h == NULL)
		errat(p->name, rec->lineno, "another polygon: a %s record "
		    "after the head of %s", recword(rec, wa, sizeof(wa)),
		    headname);
	if (rec->kind != h->kind || (rec->kind == QT_OTHER &&
	    strcmp(recword(rec, wa, sizeof(wa)), recword(h, wb, sizeof(wb)))))
		errat(p->name, rec->lineno, "another polygon: a %s record "
		    "where %s:%ld has a %s record",
		    recword(rec, wa, sizeof(wa)), headname, h->lineno,
		    recword(h, wb, sizeof(wb)));
	switch (rec->kind) {
	case QT_UNIVERSE:
		errat(p->name, rec->lineno, "another universe: %.*s, where "
		    "%s:%ld has %.*s", (int)rec->len, rec->line, headname,
		    h->lineno, (int)h->len, h->line);
		break;
	case QT_LEVEL:
		errat(p->name, rec->lineno, "another level: %.*s, where "
		    "%s:%ld has %.*s", (int)rec->len, rec->line, headname,
		    h->lineno, (int)h->len, h->line);
		break;
	case QT_RING:
		/* the line where the two rings part */
		la = rec->lineno;
		lb = h->lineno;
		for (k = 0, a = rec->line, b = h->line;
		    k < rec->len && k < h->len && a[k] == b[k]; k++)
			if (a[k] == '\n')
				la++, lb++;
		errat(p->name, la, "another polygon: ring %ld differs from "
		    "%s:%ld", rec->ring.id, headname, lb);
		break;
	default:
		errat(p->name, rec->lineno, "another polygon: %s record "
		    "differs from %s:%ld", recword(rec, wa, sizeof(wa)),
		    headname, h->lineno);
		break;
	}
}

static int readhead(struct input *);
static int pathorder(const struct cell *, const struct cell *);

/* Preorder: a 2D cell's by its grid place, a 3D one's by its path. */
static int (*cellorder)(const struct cell *, const struct cell *) = cell_cmp;

/* Input p's first record says its dimension d: the first input's. */
static void
setdim(struct input *p, int d)
{
	p->dim = d;
	if (dim == 0) {
		dim = d;
		dimname = p->name;
	} else if (d != dim)
		errat(p->name, 1, "a %dD stream, and %s holds a %dD one: qtcat "
		    "joins trees of one dimension", d, dimname, dim);
	if (d == 3) {
		lastdigit = '7';
		cellorder = pathorder;
	}
}

/*
 * The next record of input p into rec, a 3D stream's (read3.c) given as a
 * 2D one's: its text and count, a cell's path, level, class and number.
 */
static enum qtkind
readrec(struct input *p, struct qtrec *rec)
{
	struct qt3rec *r3 = &p->rec3;
	enum qtkind kind;

	if (p->s == NULL) {
		if ((kind = qt_read(p->r, rec)) != QT_SOLID) {
			if (p->dim == 0 && kind != QT_EOF)
				setdim(p, 2);
			return kind;
		}
		setdim(p, 3);
		p->s = qt3_open(p->r);
	}
	rec->kind = kind = qt3_read(p->s, r3);
	rec->line = r3->line;
	rec->len = r3->len;
	rec->lineno = r3->lineno;
	rec->nrec = r3->nrec;
	if (kind == QT_NODE || kind == QT_LEAF) {
		memset(&rec->c, 0, sizeof(rec->c));
		rec->c.path = r3->c.path;
		rec->c.level = r3->c.level;
		rec->c.class = r3->c.class;
		rec->c.id = r3->c.id;
		rec->c.frac = -1;
	} else if (kind == QT_UNIVERSE && headname == NULL)
		u3 = r3->u;
	return kind;
}

/* The next record: a 2D stream's straight from its reader once known. */
static inline enum qtkind
nextrec(struct input *p, struct qtrec *rec)
{
	return p->dim == 2 ? qt_read(p->r, rec) : readrec(p, rec);
}

/* Preorder of 3D cells: their paths', "." first. */
static int
pathorder(const struct cell *a, const struct cell *b)
{
	return strcmp(a->path, b->path);
}

/* Input p's reader closed, at its end or to open it again. */
static void
closein(struct input *p)
{
	qt3_close(p->s);
	p->s = NULL;
	qt_close(p->r);
}

/*
 * The first cell of the next stream of input p that has one, into p->rec,
 * after the stream that ended; returns 0 at the end of the input.
 */
static int
nextstream(struct input *p)
{
	while (p->s != NULL ? qt3_next(p->s) : qt_next(p->r))
		if (readhead(p))
			return 1;
	closein(p);
	p->done = 1;
	return 0;
}

/*
 * The next record of input p that is a cell, into p->rec; records of
 * other kinds between cells are written as met.  Returns 0 at the end.
 * An input's streams, one after another, are one merge source: their
 * cells must come in preorder across them too.
 */
static int
nextcell(struct input *p)
{
	enum qtkind kind;
	char path[QT_MAXLEVEL + 1];
	struct cell prev;

	prev.level = p->rec.c.level;
	prev.ix = p->rec.c.ix;
	prev.iy = p->rec.c.iy;
	if (p->s != NULL) {	/* the reader's path changes with the cell */
		memcpy(path, p->rec.c.path, strlen(p->rec.c.path) + 1);
		prev.path = path;
	}
	p->lineno = p->rec.lineno;
	for (;;) {
		switch (kind = nextrec(p, &p->rec)) {
		case QT_EOF:
			if (!nextstream(p))
				return 0;
			if (cellorder(&prev, &p->rec.c) > 0)
				errat(p->name, p->rec.lineno, "cell %s comes "
				    "before cell %s (line %ld) in preorder: "
				    "an input's streams must follow each other "
				    "in preorder", p->rec.c.path, dim == 3 ?
				    prev.path : cellpath(path, prev.level,
				    prev.ix, prev.iy), p->lineno);
			return 1;
		case QT_NODE:
		case QT_LEAF:
			return 1;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(p->r, "the input holds a mesh (%s record): "
			    "qtcat joins trees",
			    kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:	/* the reader refuses a head record after cells */
			qt_echo(&p->rec);
			break;
		}
	}
}

/*
 * Reads the head of input p's stream, up to its first cell, which goes to
 * p->rec: the first head read is kept, every other one compared with it.
 * Returns 1 at a cell, 0 at the stream's end or, when the input holds no
 * stream, at its end.
 */
static int
readhead(struct input *p)
{
	struct qtrec rec;
	enum qtkind kind;
	size_t j = 0;
	long line = 0;
	int keep = headname == NULL;

	while ((kind = nextrec(p, &rec)) != QT_EOF) {
		if (kind == QT_NODE || kind == QT_LEAF)
			break;
		if (kind == QT_VERTEX || kind == QT_ELEM)
			qt_fail(p->r, "the input holds a mesh (%s record): "
			    "qtcat joins trees",
			    kind == QT_ELEM ? "elem" : "vertex");
		if (keep) {
			if (nhead == headcap) {
				headcap = headcap ? 2 * headcap : 16;
				head = xreallocarray(head, headcap,
				    sizeof(*head));
			}
			head[nhead++] = qt_keep(&rec);
			if (kind == QT_UNIVERSE && p->s == NULL)
				qt_setuniverse(&rec.u);
		} else
			samehead(p, j, &rec, 0);
		line = rec.lineno + (long)rec.nrec - 1;
		j++;
	}
	if (kind == QT_EOF && j == 0)
		return 0;	/* no stream: each has a universe */
	if (keep)
		headname = p->name;
	else
		samehead(p, j, NULL, kind == QT_EOF ? line : rec.lineno);
	if (kind == QT_EOF)
		return 0;
	p->rec = rec;
	return 1;
}

/*
 * The cell that preorder puts after the last one in a whole tree under
 * the first: the last's first child when it is a node, else the next
 * sibling of the last or of its nearest ancestor below the root that has
 * one.  Its path goes to want; returns its level, -1 when the tree is
 * whole.
 */
static int
wanted(char *want)
{
	int j;

	if (last.class == 0) {
		memcpy(want, last.path, last.level);
		want[last.level] = '0';
		return last.level + 1;
	}
	for (j = last.level; j > root.level && last.path[j - 1] == lastdigit;
	    j--)
		;
	if (j == root.level)
		return -1;
	memcpy(want, last.path, j);
	want[j - 1]++;
	return j;
}

/*
 * Whether cell c is the one that wanted would name, without building it:
 * returns the length of the path it shares with the last cell, -1 when
 * it is another cell.
 */
static int
follows(const struct cell *c)
{
	int j = c->level, k;

	if (last.class == 0)
		return j == last.level + 1 && c->path[j - 1] == '0' &&
		    memcmp(c->path, last.path, j - 1) == 0 ? j - 1 : -1;
	if (j > last.level || j <= root.level ||
	    c->path[j - 1] != last.path[j - 1] + 1)
		return -1;
	for (k = j; k < last.level; k++)
		if (last.path[k] != lastdigit)
			return -1;
	return memcmp(c->path, last.path, j - 1) == 0 ? j - 1 : -1;
}

/*
 * Refuses cell c, read from name at lineno, which is not the one that
 * the tree's preorder puts after the last cell; returns whether to write
 * it (-u), 0 to drop it (a node given again).
 */
static int
misfit(const struct cell *c, const char *name, long lineno)
{
	char want[QT_MAXLEVEL + 1];
	int n;

	if (c->level == last.level &&
	    memcmp(c->path, last.path, c->level) == 0) {
		if (c->class == 0 && last.class == 0)
			return 0;
		errat(name, lineno, "cell %s given twice: also at %s:%ld",
		    c->path, last.name, last.lineno);
	}
	if (last.class != 0 && c->level > last.level &&
	    memcmp(c->path, last.path, last.level) == 0)
		errat(name, lineno, "cell %s lies inside leaf %s (%s:%ld)",
		    c->path, pathname(last.path, last.level), last.name,
		    last.lineno);
	if (unsealed)
		return 1;
	if ((n = wanted(want)) < 0)
		errat(name, lineno, "cell %s lies outside the tree under cell "
		    "%s (%s:%ld), the first cell: the cells above it are "
		    "missing", c->path, pathname(root.path, root.level),
		    root.name, root.lineno);
	errat(name, lineno, "cell %.*s is missing: cell %s comes after cell "
	    "%s (%s:%ld)", n, want, c->path, pathname(last.path, last.level),
	    last.name, last.lineno);
	return 0;
}

/*
 * Writes cell c, read from name at lineno, which comes after the last one
 * in preorder or is it: a node given again is written once.
 */
static void
putcell(const struct cell *c, const char *name, long lineno)
{
	int k = 0;

	if (last.have && (k = follows(c)) < 0) {
		if (!misfit(c, name, lineno))
			return;
		k = 0;
	}
	if (dim == 3) {
		struct cell3 c3;

		memset(&c3, 0, sizeof(c3));
		c3.path = c->path;
		c3.level = c->level;
		pathcell3(c->path, c->level, &c3.ix, &c3.iy, &c3.iz);
		c3.class = c->class;
		c3.id = c->id;
		qt3_cell(&u3, &c3);
	} else if (c->frac >= 0)
		qt_cellfrac(c, c->id, c->frac);
	else
		qt_cell(c, c->id);
	memcpy(last.path + k, c->path + k, c->level - k);
	last.path[c->level] = '\0';
	last.level = c->level;
	last.class = c->class;
	last.name = name;
	last.lineno = lineno;
	if (!last.have)
		root = last;
	last.have = 1;
}

/* The first head's bytes, as qtcat writes it, to compare shards with. */
static void
headbytes(void)
{
	size_t j;

	headlen = 10;
	for (j = 0; j < nhead; j++)
		headlen += head[j]->len + 1;
	headtext = xmalloc(headlen);
	headlen = dim == 3 ? 10 : 8;
	memcpy(headtext, dim == 3 ? "qtree 1 3\n" : "qtree 1\n", headlen);
	headlines = 1;
	for (j = 0; j < nhead; j++) {
		memcpy(headtext + headlen, head[j]->line, head[j]->len);
		headlen += head[j]->len;
		headtext[headlen++] = '\n';
		headrecs += head[j]->nrec;
		headlines += (long)head[j]->nrec;
	}
}

/*
 * A shard that another input has a cell among, or that follows no
 * stream: the reader reads it after all, its head again.
 */
static void
unblock(struct input *p)
{
	FILE *fp;

	close(p->b->fd);
	free(p->b);
	p->b = NULL;
	fp = openin(p->path, &p->name);
	p->r = qt_open(fp, p->name,
	    QT_NEEDUNIVERSE | QT_ARCS | QT_CONCAT | QT_SOLIDS);
	p->dim = 0;
	if (!readhead(p))
		nextstream(p);
}

/* Writes shard p whole, its first cell at its place in the merge. */
static void
putblock(struct input *p)
{
	struct block *b = p->b;
	struct cell *c = &p->rec.c;
	unsigned long long lines = 0, want = b->ncells;
	off_t at = b->from;

	if (last.have && follows(c) < 0 && !misfit(c, p->name, p->rec.lineno)) {
		at += (off_t)b->firstlen;	/* a node given again */
		want--;
	}
	if (!last.have) {
		memcpy(root.path, b->firstpath, c->level);
		root.path[c->level] = '\0';
		root.level = c->level;
		root.class = c->class;
		root.name = p->name;
		root.lineno = p->rec.lineno;
		root.have = 1;
	}
	while (at < b->to)
		at += (off_t)copyspan(p, at, &lines);
	if (lines != want)
		errat(p->name, headlines + 1 + (long)b->ncells,
		    "its end record counts %llu cells, the lines between its "
		    "head and it are %llu: a shard copied whole must be one "
		    "whole stream (qtcat -c reads every cell)", b->ncells,
		    lines + (b->ncells - want));
	qt_copy("", 0, lines);
	memcpy(last.path, b->lastpath, b->last.level);
	last.path[b->last.level] = '\0';
	last.level = b->last.level;
	last.class = b->last.class;
	last.name = p->name;
	last.lineno = p->rec.lineno + (long)b->ncells - 1;
	last.have = 1;
	close(b->fd);
	free(b);
	p->b = NULL;
	p->done = 1;
}

/* At the end of the merge, the tree must be whole. */
static void
endtree(void)
{
	char want[QT_MAXLEVEL + 1];
	int n;

	if (!last.have || unsealed || (n = wanted(want)) < 0)
		return;
	errat(last.name, last.lineno, "cell %.*s is missing: the cells end "
	    "at cell %s", n, want, pathname(last.path, last.level));
}

/* The heap of inputs by current cell, an earlier input first on a tie. */
static int
before(const struct input *a, const struct input *b)
{
	int d = cellorder(&a->rec.c, &b->rec.c);

	return d < 0 || (d == 0 && a < b);
}

static void
siftdown(struct input **h, int n, int i)
{
	struct input *p = h[i];
	int k;

	while ((k = 2 * i + 1) < n) {
		if (k + 1 < n && before(h[k + 1], h[k]))
			k++;
		if (!before(h[k], p))
			break;
		h[i] = h[k];
		i = k;
	}
	h[i] = p;
}

/* Streams of sealed inputs: a k-way merge, one cell an input held. */
static void
merge(void)
{
	struct input **h = xreallocarray(NULL, nin, sizeof(*h));
	struct input *p, *q;
	int n = 0, i;

	for (i = 0; i < nin; i++)
		if (!in[i].done)
			h[n++] = &in[i];
	for (i = n / 2 - 1; i >= 0; i--)
		siftdown(h, n, i);
	while (n > 0) {
		p = h[0];
		if (p->b != NULL) {
			/* the next cell of the other inputs, after its last? */
			q = n > 1 ? h[1] : NULL;
			if (n > 2 && before(h[2], h[1]))
				q = h[2];
			if (q != NULL &&
			    cellorder(&q->rec.c, &p->b->last) <= 0) {
				unblock(p);
				if (p->done)
					h[0] = h[--n];
				siftdown(h, n, 0);
				continue;
			}
			putblock(p);
			h[0] = h[--n];
			siftdown(h, n, 0);
			continue;
		}
		putcell(&p->rec.c, p->name, p->rec.lineno);
		if (!nextcell(p))
			h[0] = h[--n];
		siftdown(h, n, 0);
	}
	free(h);
}

static void
hold(const struct input *p)
{
	const struct cell *c = &p->rec.c;
	struct heldcell *k;

	if (nheld == heldcap) {
		heldcap = heldcap ? 2 * heldcap : 4096;
		held = xreallocarray(held, heldcap, sizeof(*held));
	}
	k = &held[nheld++];
	k->ix = c->ix;
	k->iy = c->iy;
	k->id = c->id;
	k->frac = c->frac;
	k->lineno = p->rec.lineno;
	k->input = p - in;
	k->level = c->level;
	k->class = c->class;
}

static int
heldcmp(const void *va, const void *vb)
{
	const struct heldcell *a = va, *b = vb;
	struct cell ca, cb;
	int d;

	ca.level = a->level;
	ca.ix = a->ix;
	ca.iy = a->iy;
	cb.level = b->level;
	cb.ix = b->ix;
	cb.iy = b->iy;
	if ((d = cell_cmp(&ca, &cb)) != 0)
		return d;
	if (a->input != b->input)
		return a->input < b->input ? -1 : 1;
	return (a->lineno > b->lineno) - (a->lineno < b->lineno);
}

/* Unsealed inputs: every cell held, sorted, then written. */
static void
sortcells(void)
{
	char path[QT_MAXLEVEL + 1];
	struct cell c;
	size_t i;
	int i0;

	for (i0 = 0; i0 < nin; i0++)
		if (!in[i0].done)
			do
				hold(&in[i0]);
			while (nextcell(&in[i0]));
	if (nheld > 0)	/* held is NULL without cells, which qsort may not take */
		qsort(held, nheld, sizeof(*held), heldcmp);
	memset(&c, 0, sizeof(c));
	for (i = 0; i < nheld; i++) {
		c.level = held[i].level;
		c.ix = held[i].ix;
		c.iy = held[i].iy;
		c.class = held[i].class;
		c.id = held[i].id;
		c.frac = held[i].frac;
		c.path = cellpath(path, c.level, c.ix, c.iy);
		putcell(&c, in[held[i].input].name, held[i].lineno);
	}
	free(held);
}

int
main(int argc, char *argv[])
{
	static char *stdinonly[] = { "-", NULL };
	FILE *fp;
	size_t j;
	int ch, i, nstdin = 0;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "cuh")) != -1)
		switch (ch) {
		case 'c':
			checkall = 1;
			break;
		case 'u':
			unsealed = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if (argc == 0) {
		argc = 1;
		argv = stdinonly;
	}

	nin = argc;
	in = xreallocarray(NULL, nin, sizeof(*in));
	memset(in, 0, nin * sizeof(*in));
	for (i = 0; i < nin; i++) {
		if (strcmp(argv[i], "-") == 0 && nstdin++ > 0)
			die(2, "the standard input (-) named twice");
		in[i].path = argv[i];
		if (i > 0 && headname != NULL && headtext == NULL &&
		    !unsealed && !checkall)
			headbytes();
		if (headtext != NULL && probe(&in[i], argv[i])) {
			in[i].name = argv[i];
			continue;
		}
		fp = openin(argv[i], &in[i].name);
		in[i].r = qt_open(fp, in[i].name, QT_NEEDUNIVERSE | QT_ARCS |
		    QT_SOLIDS | (unsealed ? QT_UNSEALED : QT_CONCAT));
		if (!readhead(&in[i]))
			nextstream(&in[i]);
	}
	if (headname == NULL)
		errat(in[0].name, 0, "empty input: not a qtree stream");
	if (dim == 3)
		qt3_header();
	else
		qt_header();
	for (j = 0; j < nhead; j++)
		qt_echo(head[j]);
	if (unsealed)
		sortcells();
	else
		merge();
	endtree();
	for (j = 0; j < nhead; j++)	/* the heads of later streams */
		qt_free(head[j]);
	free(head);
	free(in);
	qt_end();
	closeout();
	return 0;
}
