#!/usr/bin/env bats
# The benchmark's harnesses of p4est and CGAL (tools/bench/peers/, make
# bench-peers) count the leaves that qtsplit does; a peer that is not
# installed skips its test, visibly.
load test_helper

# peercheck PEER PACKAGES: tools/bench/benchpeers.sh -c for one peer.
peercheck() {
	cd "$TOP" || return 1
	run sh tools/bench/benchpeers.sh -c "$1"
	[ "$status" -ne 77 ] || skip "$1 is not installed (Debian $2)"
	[ "$status" -eq 0 ]
	[[ "$output" == *"the same leaves from qtsplit and $1" ]]
}

@test "the p4est harness counts qtsplit's leaves on every sample" {
	peercheck p4est "libp4est-dev, libopenmpi-dev"
}

@test "the CGAL harness counts qtsplit's leaves on every sample" {
	peercheck cgal libcgal-dev
}

@test "the CGAL octree harness counts qtsplit's leaves on solids and CGAL's meshes" {
	cd "$TOP" || return 1
	run sh tools/bench/benchpeers3.sh -c
	[ "$status" -ne 77 ] || skip "CGAL's Octree is not installed (Debian libcgal-dev)"
	[ "$status" -eq 0 ]
	[[ "$output" == *"the same leaves from qtsplit and cgal3" ]]
	# the hand-made solids agreed; the data set's meshes need libcgal-demo
	[[ "$output" != *"data set is absent"* ]] ||
		skip "CGAL's data set is absent (Debian libcgal-demo): its meshes not compared"
}
