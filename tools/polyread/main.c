/*
 * polyread: read polygons in brep, xy, wkt, Triangle poly, csv or GeoJSON
 * form, check that they make a valid region, and write them as a qtree(5)
 * stream of rings: outer rings counter-clockwise, holes clockwise.  Or a
 * solid's surface in OFF, STL, OBJ or PLY form, checked and written as a
 * 3D stream of shells, outward (solid3.c).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "polyread.h"

int verbose;
const char *readas;

/*
 * Detection tries the rows from the last up and takes the first that
 * claims the input: brep, which claims any, comes first, and a new format
 * goes last.  The -f message lists them in this order.
 */
static const struct format formats[] = {
	{ "brep",	isbrep,	parsebrep,
	    "no other format claims the first line" },
	{ "xy",		isxy,	parsexy,
	    "the first line holds two fields" },
	{ "wkt",	iswkt,	parsewkt,
	    "the first word starts with a letter" },
	{ "poly",	ispoly,	parsepoly,
	    "the first line holds four integers, the second 2" },
	{ "csv",	iscsv,	parsecsv,
	    "the first line is two fields separated by a comma" },
	{ "geojson",	isgeojson, parsegeojson,
	    "the input starts with '{'" },
	{ "off",	isoff,	parseoff,
	    "the first line is OFF" },
	{ "stl",	isstl,	parsestl,
	    "the input starts with solid and has facets, or is binary" },
	{ "obj",	isobj,	parseobj,
	    "the first word is an OBJ statement (v, f, ...)" },
	{ "ply",	isply,	parseply,
	    "the first line is ply" },
};
#define NFORMATS	(sizeof(formats) / sizeof(formats[0]))

static void
usage(int help)
{
	usageexit(help, "usage: polyread [-hv] [-F feature] [-f format] "
	    "[-l level] [-u x0,y0,size] [file ...]\n");
}

static const struct format *
formatnamed(const char *name)
{
	char list[128];
	size_t i, len = 0;

	for (i = 0; i < NFORMATS; i++)
		if (strcmp(name, formats[i].name) == 0)
			return &formats[i];
	list[0] = '\0';
	for (i = 0; i < NFORMATS && len < sizeof(list); i++)
		len += snprintf(list + len, sizeof(list) - len, "%s%s",
		    i > 0 ? ", " : "", formats[i].name);
	die(2, "-f: unknown format %s (%s)", name, list);
	return NULL;
}

/* Leaves the scanner at the input's first data, which the detectors read. */
static const struct format *
detect(struct src *s)
{
	const struct format *f = &formats[NFORMATS - 1];

	if (!skipspace(s) && s->nulline == 0)
		errat(s->name, lastline(s), "no polygon in the input");
	while (!f->detect(s))
		f--;
	return f;
}

static void
parseuniverse(const char *arg, struct universe *u)
{
	const char *p = arg, *end, *msg;
	double v[3];
	int i;

	for (i = 0; i < 3; i++) {
		if (parsereal(p, &end, &v[i]) < 0 || !parsecoordok(v[i]))
			die(2, "-u: expected x0,y0,size: %s", arg);
		p = end;
		if (i < 2 && *p++ != ',')
			die(2, "-u: expected x0,y0,size: %s", arg);
	}
	if (*p != '\0' || v[2] <= 0)
		die(2, "-u: expected x0,y0,size with size > 0: %s", arg);
	u->x0 = v[0];
	u->y0 = v[1];
	u->size = v[2];
	if ((msg = cell_univcheck(u, -1)) != NULL)
		die(2, "-u: %s", msg);
}

static void
readinput(struct input *in, const char *path, const struct format *forced,
    int choosing)
{
	static char why[128];
	const struct format *f;
	struct src s;

	readall(&s, path);
	f = detect(&s);
	if (forced != NULL)
		f = forced;
	else {
		snprintf(why, sizeof(why), "read as %s: %s", f->name, f->why);
		readas = why;
	}
	if (choosing && f->parse != parsegeojson)
		die(2, "-F: %s is read as %s: only GeoJSON has features",
		    s.name, f->name);
	if (s.nulline > 0 && f->parse != parsestl && f->parse != parseply)
		errat(s.name, s.nulline, "NUL byte in input");
	s.p = s.buf;
	s.line = 1;
	f->parse(&s, in);
	readas = NULL;
	if (s.cutline > 0)
		warnat(s.name, s.cutline, "the input ends in a number, without "
		    "a newline: if it was cut, the number may be short");
	/* rings keep pointers to the name, not to the buffer */
	free(s.buf);
}

static void
check(struct input *in)
{
	struct touch *touches;
	size_t ntouches;

	if (verbose)
		progress(1, "%llu vertices in %zu rings read", in->nvertices,
		    in->nrings);
	checkrings(in);
	if (hasarcs(in))
		touches = checkcurves(in, &ntouches);
	else
		touches = checkedges(in, &ntouches);
	if (verbose)
		progress(1, "no two edges cross or overlap");
	checknesting(in, touches, ntouches);
	free(touches);
	if (verbose)
		progress(1, "nesting and connectivity checked");
}

static void
writestream(const struct input *in, const struct universe *u, int level)
{
	size_t i;

	qt_header();
	qt_universe(u);
	if (level >= 0)
		qt_level(level);
	for (i = 0; i < in->nrings; i++) {
		const struct inring *r = &in->rings[i];
		struct ring out;

		out.id = i + 1;
		out.hole = r->depth % 2;
		out.n = r->n;
		out.v = r->v;
		out.narcs = r->narcs;
		out.arc = r->arc;
		out.mid = r->mid;
		qt_ring(&out);
	}
	qt_end();
}

int
main(int argc, char *argv[])
{
	const struct format *forced = NULL;
	struct input in;
	struct universe optu, u;
	const char *end, *msg, *uarg = NULL;
	long long level = -1;
	int ch, i, haveoptu = 0, choosing = 0;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "F:f:l:u:vh")) != -1)
		switch (ch) {
		case 'F':
			choosefeature(optarg);
			choosing = 1;
			break;
		case 'f':
			forced = formatnamed(optarg);
			break;
		case 'l':
			if (parselong(optarg, &end, &level) < 0 || *end != '\0' ||
			    level < 0 || level > QT_MAXLEVEL)
				die(2, "-l: level must be an integer from 0 to "
				    "%d: %s", QT_MAXLEVEL, optarg);
			break;
		case 'u':
			uarg = optarg;
			haveoptu = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;

	memset(&in, 0, sizeof(in));
	in.level = -1;
	for (i = 0; i == 0 || i < argc; i++)
		readinput(&in, argc > 0 ? argv[i] : "-", forced, choosing);
	if (in.solid != NULL) {
		if (in.nrings > 0)
			die(1, "2D and 3D inputs mixed: polyread reads "
			    "polygons or a solid, not both");
		check3(&in);
		write3(&in, uarg, level);
		closeout();
		return 0;
	}
	check(&in);
	/* -u wins over a universe the input declares, as polyread(1) says */
	if (haveoptu) {
		parseuniverse(uarg, &optu);
		u = optu;
		checkuniverse(&in, &u, "given with -u");
	} else if (in.haveuniverse) {
		u = in.universe;
		if ((msg = cell_univcheck(&u, -1)) != NULL)
			errat(in.universefile, 0, "%s", msg);
		checkuniverse(&in, &u, "given in the input");
	} else {
		defaultuniverse(&in, &u);
		if ((msg = cell_univcheck(&u, -1)) != NULL)
			die(1, "%s (the rings' bounding square; -u gives "
			    "another)", msg);
	}
	/* the level, -l's or the input's, within the universe's reach */
	if (level >= 0 && (msg = cell_univcheck(&u, level)) != NULL)
		die(2, "-l: %s", msg);
	if (level < 0 && in.level >= 0 &&
	    (msg = cell_univcheck(&u, in.level)) != NULL)
		errat(in.levelfile, 0, "%s", msg);
	if (level < 0)
		level = in.level;
	orientrings(&in);
	writestream(&in, &u, level);
	if (verbose)
		progress(1, "%zu rings written", in.nrings);
	freeinput(&in);
	closeout();
	return 0;
}
