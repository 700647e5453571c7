/*
 * qtstats: figures about a qtree(5) stream (its polygon, its cells, its
 * mesh) as "key value" lines, one space between, for awk.  The keys are an
 * interface: qtstats(1) lists them, and they keep their names and meaning.
 * With -s it writes instead the exact sums behind the figures, and with -m
 * it adds up such sums, of the shards of a tree, into the tree's figures.
 *
 * main.c reads the options and the stream, record by record, and writes
 * the report; a file a job: poly.c (the polygon), tree.c (the cells, the
 * figures of the tree cut at each level), jump.c (the level jumps),
 * mesh.c (the mesh), sums.c (-s), merge.c (-m) and solid.c (a 3D
 * stream: the solid and its octree).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtstats.h"

int merged;
static int stats3table;	/* -l, for a 3D stream */

static void
usage(int help)
{
	usageexit(help, "usage: qtstats [-hlmsv] [file ...]\n");
}

static void
readstream(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_SOLID:	/* a 3D stream: solid.c */
			exit(stats3main(r, stats3table));
		case QT_UNIVERSE:
			tree.u = rec.u;
			tree.haveuniverse = 1;
			break;
		case QT_RING:
			ring(&rec.ring);
			break;
		case QT_OBJECT:
			poly.nobjects = rec.object;
			break;
		case QT_NODE:
		case QT_LEAF:
			addcell(&rec.c);
			break;
		case QT_VERTEX:
			meshvertex(&rec.vertex);
			mesh.present = 1;
			break;
		case QT_ELEM:
			meshelem(&rec.elem);
			mesh.present = 1;
			break;
		default:
			break;
		}
	}
}

void
putkey(const char *key, const char *value)
{
	printf("%s %s\n", key, value);
}

void
putcount(const char *key, unsigned long long v)
{
	char buf[32];

	fmtint(buf, (long long)v);
	putkey(key, buf);
}

void
putreal(const char *key, double v)
{
	char buf[32];

	fmtreal(buf, v);
	putkey(key, buf);
}

static void
report(int table)
{
	double area = polygonfigures();

	if (tree.haveuniverse)
		putcount("universe_deepest_level",
		    cell_univdeepest(&tree.u, NULL, 0));
	cellfigures(area);
	if (mesh.present)
		meshfigures();
	if (table)
		leveltable(area);
}

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	int ch, i, table = 0, verbose = 0;

	xsetprogname(argv[0]);
	while ((ch = getopt(argc, argv, "lmsvh")) != -1)
		switch (ch) {
		case 'l':
			table = stats3table = 1;
			break;
		case 'm':
			merged = 1;
			break;
		case 's':
			sums.on = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage(ch == 'h');
		}
	argc -= optind;
	argv += optind;
	if ((argc > 1 && !merged) || (merged && (sums.on || verbose)))
		usage(0);

	area_moinit(&poly.region);
	area_moinit(&poly.ring);
	area_init(&tree.cut);
	if (merged) {
		for (i = 0; i < argc || (argc == 0 && i == 0); i++)
			mergeinput(argc > 0 ? argv[i] : "-");
		mergejoin(argc > 0 && strcmp(argv[0], "-") != 0 ? argv[0] :
		    "stdin");
		report(table);
		closeout();
		return 0;
	}
	r = qt_openpath(argc == 1 ? argv[0] : "-",
	    QT_ARCS | QT_SOLIDS | (verbose ? QT_VERBOSE : 0));
	readstream(r);
	if (sums.on)
		sumsreport(qt_name(r));
	qt_close(r);
	if (!sums.on)
		report(table);
	closeout();
	return 0;
}
