/*
 * solidcat: a 3D qtree(5) stream read by the library and written again by
 * it, shells and cells rewritten from what was read, anything else echoed;
 * for tests/solid.bats, which checks the reader and writer through it.
 */
#include <stdio.h>
#include <stdlib.h>

#include "qtree.h"

int
main(int argc, char *argv[])
{
	struct qtreader *r;
	struct qt3reader *s;
	struct qt3rec rec;
	struct qtrec rec2;
	struct universe3 u;

	xsetprogname(argv[0]);
	if (argc > 2)
		usageexit(0, "usage: solidcat [file]\n");
	r = qt_openpath(argc == 2 ? argv[1] : "-", QT_SOLIDS);
	if (qt_read(r, &rec2) != QT_SOLID)
		die(1, "not a 3D stream");
	s = qt3_open(r);
	qt3_header();
	while (qt3_read(s, &rec) != QT_EOF)
		switch (rec.kind) {
		case QT_UNIVERSE:
			u = rec.u;
			qt3_universe(&u);
			break;
		case QT_LEVEL:
			qt_level(rec.level);
			break;
		case QT_SHELL:
			qt3_shell(&rec.shell);
			break;
		case QT_NODE:
		case QT_LEAF:
			qt3_cell(&u, &rec.c);
			break;
		default:
			qt3_echo(&rec);
			break;
		}
	qt3_close(s);
	qt_close(r);
	qt_end();
	closeout();
	return 0;
}
