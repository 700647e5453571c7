#!/bin/sh
# The Debian packages the build and the suite use, in one list that make
# deps, make test and .ci/run share.  Each line: a package and the shell
# test that says it is there.  "need" packages make test cannot run
# without; "reader" packages are the real readers and peers that some
# tests use and skip visibly without.
#
#   sh tools/deps.sh		print the missing packages, one line
#   sh tools/deps.sh -n	exit 1 with the apt-get line when one that
#				make test needs is missing
#   sh tools/deps.sh -i	install every missing package (apt-get)
set -u
have() { command -v "$1" > /dev/null 2>&1; }
meshio() {
	python3 -c 'import meshio' 2> /dev/null ||
	    /usr/bin/python3 -c 'import meshio' 2> /dev/null
}
scipy() {
	python3 -c 'import scipy' 2> /dev/null ||
	    /usr/bin/python3 -c 'import scipy' 2> /dev/null
}

list() {
	cat <<-'EOF2'
	need gcc		have cc
	need make		have make
	need bats		have bats
	need mandoc		have mandoc
	need python3		have python3
	reader libxml2-utils	have xmllint
	reader librsvg2-bin	have rsvg-convert
	reader netpbm		have pngtopnm
	reader gdal-bin		have ogrinfo
	reader valgrind		have valgrind
	reader time		[ -x /usr/bin/time ]
	reader locales		have localedef && [ -f /usr/share/i18n/locales/de_DE ]
	reader afl++		have afl-clang-fast
	reader parallel		have parallel
	reader openssh-server	[ -x /usr/sbin/sshd ]
	reader rsync		have rsync
	reader libp4est-dev	[ -f /usr/include/p4est_extended.h ]
	reader libopenmpi-dev	have mpicc
	reader libcgal-dev	[ -f /usr/include/CGAL/version.h ]
	reader libcgal-demo	[ -f /usr/share/doc/libcgal-dev/data.tar.gz ]
	reader python3-meshio	meshio
	reader python3-scipy	scipy
	reader gmsh		have gmsh
	reader calculix-ccx	have ccx
	EOF2
}

# missing KIND: the missing packages of that kind (any: all kinds).
missing() {
	list | while read -r kind pkg check; do
		[ "$1" = any ] || [ "$1" = "$kind" ] || continue
		eval "$check" || printf '%s ' "$pkg"
	done
}

case ${1:-} in
'')	missing any; echo ;;
-n)	need=$(missing need)
	[ -z "$need" ] && exit 0
	echo "make test needs: $need(sudo apt-get install -y $need$(missing reader)or make deps)" >&2
	exit 1 ;;
-i)	all=$(missing any)
	[ -n "$all" ] || exit 0
	sudo=
	[ "$(id -u)" -eq 0 ] || sudo=sudo
	export DEBIAN_FRONTEND=noninteractive
	$sudo apt-get update -qq &&
	    # shellcheck disable=SC2086
	    $sudo apt-get install -y -qq $all ;;
*)	echo "usage: sh tools/deps.sh [-n | -i]" >&2
	exit 2 ;;
esac
