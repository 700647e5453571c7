# qtree: quadtree decomposition of polygons, as small Unix filters.
.POSIX:
.SUFFIXES:

PREFIX = /usr/local
MANPREFIX = $(PREFIX)/share/man
CC = cc
CFLAGS = -O2 -g -Wall -Wextra
QTCFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -ffp-contract=off -Ilib
LDLIBS = -lm

BIN = polyread qtsplit qtleaves qtstats qt2svg qtcat qtmesh qtbalance qtbool
MAN1 = man/polyread.1 man/qtsplit.1 man/qtleaves.1 man/qtstats.1 \
	man/qt2svg.1 man/qtcat.1 man/qtmesh.1 man/qtbalance.1 man/qtbool.1
MAN5 = man/qtree.5
QTREEH = lib/qtree.h lib/arcfilter.h	# the public header and what it includes
LIBOBJ = lib/msg.o lib/hugepage.o lib/parse.o lib/fmt.o lib/geom.o lib/cell.o lib/read.o \
	lib/write.o lib/area.o lib/cellset.o lib/corner.o lib/split.o \
	lib/pow5.o lib/op.o lib/arc.o lib/arccheck.o lib/bigint.o lib/cut.o \
	lib/earclip.o lib/celltext.o lib/readhead.o lib/solid.o lib/read3.o \
	lib/write3.o lib/split3.o lib/volfrac.o

all: $(BIN)

$(LIBOBJ): $(QTREEH)
$(LIBOBJ): lib/num.h lib/celltext.h lib/inline.h lib/exact.h lib/reader.h
lib/libqtree.a: $(LIBOBJ)
	rm -f $@
	ar rc $@ $(LIBOBJ)
	ranlib $@

.SUFFIXES: .c .o
.c.o:
	$(CC) $(QTCFLAGS) $(CFLAGS) -c -o $@ $<

# polyread has a directory of its own, a file a job.
POLYREADOBJ = tools/polyread/main.o tools/polyread/src.o \
	tools/polyread/brep.o tools/polyread/xy.o tools/polyread/wkt.o \
	tools/polyread/poly.o tools/polyread/csv.o tools/polyread/geojson.o \
	tools/polyread/valid.o tools/polyread/sweep.o tools/polyread/curve.o \
	tools/polyread/touch.o tools/polyread/solid3.o tools/polyread/off.o \
	tools/polyread/stl.o tools/polyread/obj.o tools/polyread/ply.o
# So has qtmesh.
QTMESHOBJ = tools/qtmesh/main.o tools/qtmesh/tree.o tools/qtmesh/conform.o \
	tools/qtmesh/bfit.o tools/qtmesh/boundary.o tools/qtmesh/join.o \
	tools/qtmesh/rcm.o tools/qtmesh/write.o tools/qtmesh/refine.o \
	tools/qtmesh/arcs.o tools/qtmesh/inp.o tools/qtmesh/order2.o \
	tools/qtmesh/angles.o
$(BIN): lib/libqtree.a
polyread: $(POLYREADOBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $(POLYREADOBJ) lib/libqtree.a $(LDLIBS)
qtsplit: tools/qtsplit.o tools/qtsplit3.o
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ tools/qtsplit.o tools/qtsplit3.o lib/libqtree.a $(LDLIBS)
qtleaves: tools/qtleaves.o
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ tools/qtleaves.o lib/libqtree.a $(LDLIBS)
# qtstats too: main.c, poly.c, tree.c, jump.c, mesh.c, sums.c, merge.c,
# solid.c.
QTSTATSOBJ = tools/qtstats/main.o tools/qtstats/poly.o \
	tools/qtstats/tree.o tools/qtstats/jump.o tools/qtstats/mesh.o \
	tools/qtstats/sums.o tools/qtstats/merge.o tools/qtstats/solid.o
$(QTSTATSOBJ): $(QTREEH) tools/qtstats/qtstats.h
qtstats: $(QTSTATSOBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $(QTSTATSOBJ) lib/libqtree.a $(LDLIBS)
# qt2svg too: main.c, out.c, window.c, leaves.c, rings.c, mesh.c,
# quality.c, legend.c, solid.c, iso.c.
QT2SVGOBJ = tools/qt2svg/main.o tools/qt2svg/out.o tools/qt2svg/window.o \
	tools/qt2svg/leaves.o tools/qt2svg/rings.o tools/qt2svg/mesh.o \
	tools/qt2svg/quality.o tools/qt2svg/legend.o tools/qt2svg/solid.o \
	tools/qt2svg/iso.o
$(QT2SVGOBJ): $(QTREEH) tools/qt2svg/qt2svg.h
qt2svg: $(QT2SVGOBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $(QT2SVGOBJ) lib/libqtree.a $(LDLIBS)
qtcat: tools/qtcat.o tools/qtcatcopy.o
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ tools/qtcat.o tools/qtcatcopy.o \
	    lib/libqtree.a $(LDLIBS)
qtmesh: $(QTMESHOBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $(QTMESHOBJ) lib/libqtree.a $(LDLIBS)
qtbalance: tools/qtbalance.o
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ tools/qtbalance.o lib/libqtree.a $(LDLIBS)
qtbool: tools/qtbool.o
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ tools/qtbool.o lib/libqtree.a $(LDLIBS)
$(POLYREADOBJ): $(QTREEH) tools/polyread/polyread.h
$(QTMESHOBJ): $(QTREEH) tools/qtmesh/qtmesh.h
tools/qtsplit.o tools/qtsplit3.o: tools/qtsplit.h
tools/qtcat.o tools/qtcatcopy.o: tools/qtcat.h
tools/qtsplit.o tools/qtsplit3.o tools/qtleaves.o \
tools/qtcat.o tools/qtcatcopy.o tools/qtbalance.o \
tools/qtbool.o: $(QTREEH)

# Test programs: fmtcheck checks fmtreal against printf and strtod,
# fmtbench times it; numcheck checks parsereal against strtod, numbench
# times both (tools/bench/benchnum.sh).  genpow5 writes lib/pow5.c, which is
# committed (tests/lib-numbers.bats compares).  rangecheck checks qtree(5)'s
# range rule; predcheck prints incircle's and orient2d's signs, orient3check
# orient3d's.
tests/check/fmtcheck: tests/check/fmtcheck.c tests/check/splitmix.h lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/fmtcheck.c lib/libqtree.a $(LDLIBS)
tools/bench/fmtbench: tools/bench/fmtbench.c tests/check/splitmix.h lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -Itests/check -o $@ tools/bench/fmtbench.c lib/libqtree.a $(LDLIBS)
tests/check/numcheck: tests/check/numcheck.c tests/check/splitmix.h lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/numcheck.c lib/libqtree.a $(LDLIBS)
tools/bench/numbench: tools/bench/numbench.c lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tools/bench/numbench.c lib/libqtree.a $(LDLIBS)
tools/gen/genpow5: tools/gen/genpow5.c
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tools/gen/genpow5.c

tests/check/rangecheck: tests/check/rangecheck.c tests/check/splitmix.h lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/rangecheck.c lib/libqtree.a $(LDLIBS)

tests/check/predcheck: tests/check/predcheck.c lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/predcheck.c lib/libqtree.a $(LDLIBS)
tests/check/solidcat: tests/check/solidcat.c lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/solidcat.c lib/libqtree.a $(LDLIBS)
tests/check/orient3check: tests/check/orient3check.c lib/libqtree.a
	$(CC) $(QTCFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ tests/check/orient3check.c lib/libqtree.a $(LDLIBS)

# What the suite runs beyond the programs; tests/mutate.sh builds it too.
testprogs: all tests/check/fmtcheck tests/check/numcheck tools/gen/genpow5 tests/check/rangecheck \
	tests/check/predcheck tests/check/solidcat tests/check/orient3check

# What the suite needs from Debian: make deps installs it all; make test
# stops at once, naming the apt-get line, when bats or mandoc is missing.
deps:
	sh tools/deps.sh -i

test:
	@sh tools/deps.sh -n
	@$(MAKE) testprogs
	mandoc -T lint -W warning $(MAN1) $(MAN5)
	sh tests/run.sh

# The slowest tests alone (tests/long.txt), which make test skips.
check-long:
	@sh tools/deps.sh -n
	@$(MAKE) testprogs
	QTREE_LONG=only sh tests/run.sh

# The report's case 1 through the whole pipeline: the README's gallery
# (tests/gallery.bats fails when these files are stale) and the figures.
# Then the finite-element mesh: balanced, conforming, around the hole.
GALLERY = samples/amoeba-4.svg samples/amoeba-6.svg samples/amoeba-8.svg \
	samples/amoeba-mesh.svg samples/amoeba-disc.svg
demo: all
	for l in 4 6 8; do \
	    ./polyread samples/amoeba.brep | ./qtsplit -l $$l | ./qt2svg \
	    > samples/amoeba-$$l.svg || exit 1; done
	./polyread samples/amoeba.brep | ./qtsplit -l 6 | ./qtbalance | \
	    ./qtmesh | ./qt2svg -w 600 -b 8,8,14,14 > samples/amoeba-mesh.svg
	t=$$(mktemp -d) && ./polyread samples/amoeba.brep | ./qtsplit -l 7 \
	    > $$t/a && awk -v shape=disc -v n=64 -v cx=12 -v cy=10 -v r=2.5 \
	    -f tools/gen/genpoly.awk | ./polyread -u 4,4,12.2 | ./qtsplit -l 7 | \
	    ./qtbool -o and $$t/a - | ./qt2svg > samples/amoeba-disc.svg; \
	    s=$$?; rm -rf $$t; exit $$s
	@echo "wrote $(GALLERY)"
	./polyread samples/amoeba.brep | ./qtsplit -l 8 | ./qtstats

# make test's suite again with the address and undefined-behaviour
# sanitizers (the long tests, which make check-long runs plain, would take
# CI past half an hour); the sanitized programs are removed afterwards.
SANFLAGS = -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all \
	-fno-omit-frame-pointer
sanitize:
	$(MAKE) clean
	QTREE_SANITIZE=1 $(MAKE) CFLAGS="$(SANFLAGS) -Wall -Wextra" \
	    LDFLAGS="$(SANFLAGS)" test
	$(MAKE) clean

# The outputs of every program on every sample against the saved ones.
regress: all
	sh tests/regress.sh

# Mutation testing, by hand and not in test: each mutant of
# tests/mutants.txt applied alone to a scratch copy, built and tested
# (minutes); the caught, the survivors and the score.
mutate:
	sh tests/mutate.sh

# Times polyread and qtsplit on generated polygons and draws tools/bench/results/bench.svg.
bench: all tools/bench/numbench
	sh tools/bench/bench.sh

# qtree against p4est and CGAL, each when installed: counts checked, one
# table of seconds (tools/bench/benchpeers.sh); octrees against CGAL's
# Octree on CGAL's meshes, seconds and memory (tools/bench/benchpeers3.sh).
bench-peers: all
	sh tools/bench/benchpeers.sh
	sh tools/bench/benchpeers3.sh

# Shards against one run: parallel -k | qtcat, shard files and one qtcat,
# the figures by qtstats -s and -m, at -j 1 and -j 2, cut at levels 2 and
# 1, the CPU by stage; level 22 reduced to figures; saved as
# tools/bench/results/shards.txt (tools/bench/benchshards.sh).
bench-shards: all
	{ BENCH_SHARDCUT=2 BENCH_SHARDDEEP=22 sh tools/bench/benchshards.sh && \
	    BENCH_SHARDCUT=1 sh tools/bench/benchshards.sh; } \
	    > tools/bench/results/shards.txt.new && \
	    mv tools/bench/results/shards.txt.new tools/bench/results/shards.txt && \
	    cat tools/bench/results/shards.txt

# qtree's boundary-fitted mesh against Gmsh's: elements, angles, P1 error,
# time and memory, one table, saved as tools/bench/results/mesh.txt; then
# the stress concentration CalculiX gets on the plate with a hole from
# each, saved as tools/bench/results/kt.txt.
bench-mesh: all
	sh tools/bench/benchmesh.sh > tools/bench/results/mesh.txt.new && \
	    mv tools/bench/results/mesh.txt.new tools/bench/results/mesh.txt && cat tools/bench/results/mesh.txt
	sh tools/bench/benchkt.sh > tools/bench/results/kt.txt.new && \
	    mv tools/bench/results/kt.txt.new tools/bench/results/kt.txt && cat tools/bench/results/kt.txt

# Each parser under AFL++ for FUZZTIME seconds (default 60), or FUZZEXECS
# executions; FUZZMODE=fast for the persistent build (tests/fuzz/run.sh).
fuzz:
	sh tests/fuzz/run.sh

install: all
	mkdir -p $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(MANPREFIX)/man1 \
	    $(DESTDIR)$(MANPREFIX)/man5
	cp -f $(BIN) $(DESTDIR)$(PREFIX)/bin/
	cp -f $(MAN1) $(DESTDIR)$(MANPREFIX)/man1/
	cp -f $(MAN5) $(DESTDIR)$(MANPREFIX)/man5/

uninstall:
	for f in $(BIN); do rm -f $(DESTDIR)$(PREFIX)/bin/$$f; done
	for f in $(MAN1); do rm -f $(DESTDIR)$(MANPREFIX)/man1/$${f#man/}; done
	for f in $(MAN5); do rm -f $(DESTDIR)$(MANPREFIX)/man5/$${f#man/}; done

clean:
	rm -f $(BIN) lib/*.o lib/libqtree.a tools/*.o tests/check/fmtcheck \
	    tools/bench/fmtbench tests/check/numcheck tools/bench/numbench tools/gen/genpow5 \
	    tests/check/rangecheck tests/check/predcheck tests/check/solidcat \
	    tests/check/orient3check \
	    tests/fuzz/polyread tests/fuzz/qtsplit tests/fuzz/qtstats \
	    tests/fuzz/qtleaves tests/fuzz/qtbalance tests/fuzz/qtmesh tests/fuzz/qtcat \
	    tests/fuzz/qt2svg tests/fuzz/qtbool tests/fuzz/persist.o
	rm -f $(POLYREADOBJ) $(QTMESHOBJ) $(QT2SVGOBJ) $(QTSTATSOBJ)

.PHONY: all deps testprogs test check-long demo regress mutate bench bench-peers bench-mesh \
	bench-shards sanitize \
	fuzz install \
	uninstall clean
