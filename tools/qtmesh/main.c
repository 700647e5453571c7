/*
 * qtmesh: the kept leaves of a qtree(5) tree as a finite-element mesh:
 * conforming templates (conform.c), hanging vertices (-H), or the region
 * inside each leaf fitted to the rings (-b, bfit.c), numbered by first
 * use or by reverse Cuthill-McKee (-r, rcm.c), and written in one of the
 * formats of the table below (write.c).  This file reads the options and
 * the stream and runs the jobs in turn; each keeps its state in the one
 * struct mesh (qtmesh.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtmesh.h"

/*
 * -a: past 30 degrees Ruppert's refinement is no longer sure to end (its
 * proof holds to 20.7, and in practice to about 33)
 */
#define MAXANGLE	30.0

/* The formats of -f, in the order of QTREE, MSH, VTK, TRIANGLE and INP. */
static const struct writer {
	const char	*name;
	void		(*write)(const struct mesh *, size_t, const uint32_t *);
} writers[] = {
	{ "qtree",	writeqtree },
	{ "msh",	writemsh },
	{ "vtk",	writevtk },
	{ "triangle",	writetriangle },
	{ "inp",	writeinp },
};
#define NWRITERS	(sizeof(writers) / sizeof(writers[0]))

static void
usage(int help)
{
	usageexit(help, "usage: qtmesh [-2bHhrTv] [-a angle] [-c classes] "
	    "[-e family] [-f format] [-o basename] [-t fraction] [file]\n");
}

/* The format named, as its index in writers. */
static int
formatnamed(const char *name)
{
	char list[128];
	size_t i, len = 0;

	for (i = 0; i < NWRITERS; i++)
		if (strcmp(name, writers[i].name) == 0)
			return (int)i;
	list[0] = '\0';
	for (i = 0; i < NWRITERS && len < sizeof(list); i++)
		len += snprintf(list + len, sizeof(list) - len, "%s%s",
		    i == 0 ? "" : i + 1 < NWRITERS ? ", " : " or ",
		    writers[i].name);
	die(2, "-f: unknown format %s (%s)", name, list);
	return -1;
}

/* The options into m; 1 when -c was given, 2 when -a was, 4 when -e was. */
static int
options(struct mesh *m, int argc, char *argv[])
{
	const char *end;
	int ch, cflag = 0;

	while ((ch = getopt(argc, argv, "2HTa:bc:e:f:o:rt:vh")) != -1)
		switch (ch) {
		case '2':
			m->order = 2;
			break;
		case 'a':
			if (parsereal(optarg, &end, &m->minangle) < 0 ||
			    *end != '\0' || !(m->minangle >= 0 &&
			    m->minangle <= MAXANGLE))
				die(2, "-a: not an angle from 0 to %g degrees: "
				    "%s", MAXANGLE, optarg);
			cflag |= 2;
			break;
		case 'b':
			m->bfit = 1;
			break;
		case 'H':
			m->conform = 0;
			break;
		case 'T':
			m->alltri = 1;
			break;
		case 'c':
			m->keep = cell_optclasses(optarg);
			cflag |= 1;
			break;
		case 'e':
			m->family = inpfamily(optarg);
			cflag |= 4;
			break;
		case 'f':
			m->format = formatnamed(optarg);
			break;
		case 'o':
			m->outbase = optarg;
			break;
		case 'r':
			m->renumber = 1;
			break;
		case 't':
			if (parsereal(optarg, &end, &m->tfrac) < 0 ||
			    *end != '\0' || !(m->tfrac >= 0 && m->tfrac <= 1))
				die(2, "-t: not a fraction from 0 to 1: %s",
				    optarg);
			break;
		case 'v':
			m->verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	return cflag;
}

/* Options that do not go together, and what -f triangle implies. */
static void
checkoptions(struct mesh *m, int cflag)
{
	if ((m->format == TRIANGLE) != (m->outbase != NULL))
		die(2, m->format == TRIANGLE ? "-f triangle needs -o basename" :
		    "-o is for -f triangle only");
	if ((cflag & 4) && m->format != INP)
		die(2, "-e names the elements of -f inp: not without it");
	if (m->format == INP && !m->conform)
		die(2, "-f inp writes a conforming mesh: not with -H");
	if (m->tfrac >= 0 && !m->bfit)
		die(2, "-t joins the cut pieces of -b: not without it");
	if ((cflag & 2) && !m->bfit)
		die(2, "-a bounds the angles of -b: not without it");
	if (m->tfrac >= 0 && (cflag & 2) && m->minangle > 0)
		die(2, "-t joins the pieces of the cut as it is: -a 0 or no "
		    "-a with it");
	if (m->tfrac >= 0)
		m->minangle = 0;
	if (m->bfit && (!m->conform || (cflag & 1)))
		die(2, "-b meshes the region, from the F and P leaves: not "
		    "with %s", (cflag & 1) ? "-c" : "-H");
	if (m->format == TRIANGLE)
		m->alltri = 1;
	if (m->order == 2 && (m->format == QTREE || m->format == TRIANGLE))
		die(2, "-2 writes -f msh, vtk or inp: the %s format holds "
		    "corners only", m->format == QTREE ? "qtree" : "triangle");
	if (m->order == 2 && !m->conform)
		die(2, "-2 needs a conforming mesh: not with -H");
}

/* A kept leaf as read: its place, class and line, its sides not yet known. */
static void
addleaf(struct mesh *m, const struct qtrec *rec)
{
	const struct cell *c = &rec->c;
	struct leaf *l;

	m->leaves = xgrow(m->leaves, &m->leafcap, m->nleaves + 1,
	    sizeof(*m->leaves));
	l = &m->leaves[m->nleaves++];
	l->ix = c->ix;
	l->iy = c->iy;
	l->level = c->level;
	l->class = c->class;
	l->lineno = rec->lineno;
	l->hang = l->bnd = l->nel = 0;
}

/*
 * The stream: its kept leaves and, with -b, its rings; with -f qtree its
 * header echoed as it comes.
 */
static void
readtree(struct mesh *m, struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;
	int head = m->format == QTREE;

	if (head)
		qt_header();
	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			m->u = rec.u;
			if (m->bfit)
				m->b.cutter = cut_new(&rec.u);
			if (head)
				qt_universe(&rec.u);
			break;
		case QT_LEVEL:
			if (head)
				qt_level(rec.level);
			break;
		case QT_RING:
			if (m->bfit)
				keepring(m, &rec.ring, rec.lineno);
			if (head)
				qt_ring(&rec.ring);
			break;
		case QT_OBJECT:
			if (m->bfit)
				qt_fail(r, "-b: the cells of a combined stream "
				    "are not those of its rings");
			if (head)
				qt_echo(&rec);
			break;
		case QT_NODE:
			break;
		case QT_LEAF:
			/* with arcs, chords class the leaves again (arcs.c) */
			if ((m->keep & CELL_CLASSBIT(rec.c.class)) ||
			    (m->bfit && m->b.hasarcs))
				addleaf(m, &rec);
			break;
		case QT_VERTEX:
		case QT_ELEM:
			qt_fail(r, "the input already holds a mesh (%s record): "
			    "qtmesh reads a tree",
			    kind == QT_ELEM ? "elem" : "vertex");
			break;
		default:
			if (head)
				qt_echo(&rec);
			break;
		}
	}
}

/*
 * The command line, its words joined by spaces, for the heading of -f
 * inp; a control character, which would end the heading's line, as '?'.
 */
static char *
commandline(int argc, char *argv[])
{
	size_t len = 1, at = 0;
	char *s, *p;
	int i;

	for (i = 0; i < argc; i++)
		len += strlen(argv[i]) + 1;
	s = xmalloc(len);
	for (i = 0; i < argc; i++) {
		if (i > 0)
			s[at++] = ' ';
		for (p = argv[i]; *p != '\0'; p++)
			s[at++] = (unsigned char)*p < ' ' || *p == 127 ? '?' :
			    *p;
	}
	s[at] = '\0';
	return s;
}

/* -v: the mesh's figures and its bandwidth, bw0 before -r. */
static void
report(const struct mesh *m, size_t nv, uint32_t bw0)
{
	fprintf(stderr, "%s: %zu leaves, %zu vertices, %zu elements",
	    progname, m->nleaves, nv, m->nelems);
	if (m->order == 2)
		fprintf(stderr, ", %zu mid-side nodes", m->nmid);
	if (!m->conform)
		fprintf(stderr, ", %zu hanging vertices", m->g.nhangs);
	fprintf(stderr, "\n");
	if (m->renumber)
		fprintf(stderr, "%s: bandwidth %lu, %lu before "
		    "renumbering\n", progname,
		    (unsigned long)bandwidth(m), (unsigned long)bw0);
	else
		fprintf(stderr, "%s: bandwidth %lu\n", progname,
		    (unsigned long)bw0);
}

int
main(int argc, char *argv[])
{
	/*
	 * Static, so that what it holds stays reachable until the exit
	 * frees it, as a leak checker (make sanitize) sees it.
	 */
	static struct mesh m;
	struct qtreader *r;
	FILE *fp;
	uint32_t *inv, bw0 = 0;
	size_t i, nv;
	int cflag;

	xsetprogname(argv[0]);
	m.keep = CELL_CLASSBIT('F') | CELL_CLASSBIT('P');
	m.conform = 1;
	m.format = QTREE;
	m.tfrac = -1;
	m.minangle = 20;
	m.order = 1;
	m.command = commandline(argc, argv);
	cflag = options(&m, argc, argv);
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage(0);
	checkoptions(&m, cflag);
	inittemplates(&m);

	fp = openin(argc == 1 ? argv[0] : "-", &m.inname);
	r = qt_open(fp, m.inname, QT_NEEDUNIVERSE | QT_ARCS |
	    (m.verbose ? QT_VERBOSE : 0));
	readtree(&m, r);
	qt_close(r);
	if (m.bfit)
		chordrings(&m);

	findsides(&m);
	nv = m.bfit ? bfitmesh(&m) : gridmesh(&m);
	m.perm = xreallocarray(NULL, nv + 1, sizeof(*m.perm));
	for (i = 0; i < nv; i++)
		m.perm[i] = i + 1;
	if (m.verbose)
		bw0 = bandwidth(&m);
	if (m.renumber && nv > 0)
		rcm(&m, nv);
	if (m.order == 2)
		midnodes(&m);
	if (m.verbose)
		report(&m, nv, bw0);
	inv = inverse(&m, nv);
	writers[m.format].write(&m, nv, inv);
	closeout();
	free(inv);
	free((char *)m.command);
	return 0;
}
