#!/usr/bin/env bats
# Shards over GNU parallel: qtsplit -s lists the roots of a cut, parallel -k
# runs qtsplit -r on each, qtcat joins their streams with the top (-t), and
# the result is byte for byte a single run, for every level of the cut;
# qtsplit(1)'s recipes, the multi-host one run for real against an sshd on
# 127.0.0.1, each extracted from the page and run at level 8.

load test_helper

need_parallel() {
	command -v parallel >/dev/null 2>&1 ||
		skip "GNU parallel is absent (Debian package parallel)"
}

# sharded FILE LEVEL K: qtsplit(1)'s one-machine recipe, two jobs at a time.
sharded() {
	qtsplit -l "$2" -t "$3" "$1" > top.qt || return 1
	qtsplit -l "$2" -s "$3" "$1" |
	    parallel --will-cite -j 2 -k qtsplit -l "$2" -r {} "$1" |
	    qtcat top.qt -
}

# same FILE LEVEL K...: the sharded stream of each cut is the single run's.
same() {
	f=$1 l=$2
	shift 2
	qtsplit -l "$l" "$f" > whole.qt
	for k in "$@"; do
		sharded "$f" "$l" "$k" > out.qt
		cmp out.qt whole.qt || { echo "cut at level $k differs"; return 1; }
	done
}

@test "every sample, cut at every level from 0 to the tree's: the single run's bytes" {
	need_parallel
	for f in "$SAMPLES"/*.brep "$SAMPLES"/*.xy "$SAMPLES"/*.wkt \
	    "$SAMPLES"/*.poly; do
		polyread "$f" > p.qt
		same p.qt 6 0 1 2 3 4 5 6 7
	done
}

@test "a real coastline, Norway's at level 14, cut at levels 0, 2, 4 and 14" {
	need_parallel
	need_shared
	polyread "$SHARED/countries/nor_mainland_ne10m.xy" > p.qt
	[ "$(qtsplit -l 14 -s 4 p.qt | wc -l)" -gt 40 ]
	same p.qt 14 0 2 4 14
}

@test "a generated star of 10^5 vertices at level 12, cut at levels 0, 1, 3 and 12" {
	need_parallel
	awk -v shape=star -v n=100000 -f "$TOP/tools/gen/genpoly.awk" | polyread > p.qt
	[ "$(grep -c "^v " p.qt)" -eq 100004 ]	# and the hole's 4
	same p.qt 12 0 1 3 12
}

@test "two jobs for all the shards (parallel -X, qtsplit -o): the files joined by qtcat are the single run's bytes" {
	need_parallel
	awk -v shape=star -v n=10000 -f "$TOP/tools/gen/genpoly.awk" | polyread > p.qt
	qtsplit -l 12 p.qt > whole.qt
	for k in 0 1 2 3; do
		rm -rf s && mkdir s
		qtsplit -l 12 -t $k p.qt > top.qt
		qtsplit -l 12 -s $k p.qt > roots
		parallel --will-cite -j 2 -X 'qtsplit -l 12 -r{} -o s/%s.qt p.qt' \
		    < roots
		# a file a root, named by it
		ls -A s | sed 's/\.qt$//' | diff - roots
		qtcat top.qt $(sed 's|.*|s/&.qt|' roots) | cmp - whole.qt
		qtcat -c top.qt $(sed 's|.*|s/&.qt|' roots) | cmp - whole.qt
	done
}

@test "a cut with no shards: the top alone is the tree, parallel runs nothing" {
	need_parallel
	polyread "$SAMPLES/invl.brep" > p.qt
	[ -z "$(qtsplit -l 20 -s 1 p.qt)" ]
	same p.qt 20 1 2
}

@test "qtsplit(1): the example of shards prints what the page says" {
	need_parallel
	cp "$SAMPLES/amoeba.brep" .
	polyread amoeba.brep > amoeba.qt
	qtsplit -l 8 amoeba.qt > whole.qt
	[ "$(qtsplit -l 8 -s 3 amoeba.qt | wc -l)" -eq 42 ]
	qtsplit -l 8 -t 3 amoeba.qt > top.qt
	run -0 bash -c 'qtsplit -l 8 -s 3 amoeba.qt |
	    parallel --will-cite -j 2 -k qtsplit -l 8 -r {} amoeba.qt |
	    qtcat top.qt - | cmp - whole.qt && echo same'
	[ "$output" = same ]
}

# page TEXT: the commands of qtsplit(1)'s example that holds TEXT, at
# level 8, parallel told that we cite it.
page() {
	example "$TOP/man/qtsplit.1" "$1" | commands |
	    sed 's/-l 16/-l 8/g; s/parallel /parallel --will-cite /'
}

@test "qtsplit(1): filtered where the shards are made, sealed by qtcat -u" {
	need_parallel
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 p.qt | grep -v ' E$' | qtcat -u > want.qt
	# the page's recipe: the shards' nodes and full and partial leaves
	page "grep -E '^(node|leaf" > recipe.sh
	[ "$(wc -l < recipe.sh)" -eq 4 ]
	bash recipe.sh
	cmp fp.qt want.qt
	# the full leaves counted in each shard and in the top, summed
	page 'awk '"'"'{ n += $1 } END { print n }'"'" > count.sh
	[ "$(wc -l < count.sh)" -eq 4 ]
	n=$(bash count.sh)
	[ "$n" -eq "$(qtsplit -l 8 p.qt | grep -c ' F$')" ]
}

# An sshd of its own on 127.0.0.1, a high port, with throwaway keys; the
# ssh client's options in ssh.cfg under the host name qtree-test.
start_sshd() {
	[ -x /usr/sbin/sshd ] ||
		skip "sshd is absent (Debian package openssh-server)"
	command -v rsync >/dev/null 2>&1 ||
		skip "rsync is absent: parallel moves files with it"
	d=$BATS_TEST_TMPDIR/ssh
	mkdir -p "$d"
	ssh-keygen -q -t ed25519 -N '' -f "$d/host" || return 1
	ssh-keygen -q -t ed25519 -N '' -f "$d/user" || return 1
	cp "$d/user.pub" "$d/authorized_keys"
	# privilege separation needs its directory when sshd runs as root
	[ "$(id -u)" -ne 0 ] || mkdir -p /run/sshd
	for port in $(seq $((30000 + $$ % 20000)) $((30019 + $$ % 20000))); do
		cat > "$d/sshd.cfg" <<-EOF
		Port $port
		ListenAddress 127.0.0.1
		HostKey $d/host
		AuthorizedKeysFile $d/authorized_keys
		PidFile $d/sshd.pid
		UsePAM no
		StrictModes no
		PermitRootLogin yes
		PasswordAuthentication no
		KbdInteractiveAuthentication no
		EOF
		/usr/sbin/sshd -f "$d/sshd.cfg" -E "$d/sshd.log" || continue
		# the ssh connections of parallel's steps share one master
		cat > "$d/ssh.cfg" <<-EOF
		Host qtree-test
		    HostName 127.0.0.1
		    Port $port
		    User $(id -un)
		    IdentityFile $d/user
		    IdentitiesOnly yes
		    StrictHostKeyChecking no
		    UserKnownHostsFile /dev/null
		    BatchMode yes
		    LogLevel ERROR
		    ControlMaster auto
		    ControlPath $d/cm-%C
		    ControlPersist 60
		EOF
		for i in $(seq 50); do
			ssh -F "$d/ssh.cfg" qtree-test true 2>/dev/null &&
				return 0
			sleep 0.2
		done
		stop_sshd
	done
	# a machine whose sshd cannot run for this user is not a failure of
	# the recipe: say so and why
	skip "sshd would not start here: $(tail -n 1 "$d/sshd.log" 2>/dev/null)"
}

stop_sshd() {
	d=$BATS_TEST_TMPDIR/ssh
	[ -f "$d/ssh.cfg" ] && ssh -F "$d/ssh.cfg" -O exit qtree-test 2>/dev/null
	[ -f "$d/sshd.pid" ] && kill "$(cat "$d/sshd.pid")"
	rm -f "$d/sshd.pid"
}

teardown() {
	stop_sshd 2>/dev/null || true
}

@test "qtsplit(1): the multi-host recipe over ssh, input by --basefile, shards back by --return" {
	need_parallel
	start_sshd
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 p.qt > whole.qt
	echo 2/qtree-test > hosts
	# the page's recipe, cut at level 1; ssh through our sshd, the
	# programs' directory on the remote PATH
	ssh="--ssh 'ssh -F $BATS_TEST_TMPDIR/ssh/ssh.cfg' --env PATH"
	ssh="$ssh --wd '$BATS_TEST_TMPDIR/remote'"
	page '--return {}.qt' | sed "s/-t 3/-t 1/; s/-s 3/-s 1/;
	    s|parallel --will-cite |&$ssh |" > recipe.sh
	[ "$(wc -l < recipe.sh)" -eq 6 ]
	bash recipe.sh
	[ "$(ls [0-3].qt | wc -l)" -eq 4 ]
	cmp tree.qt whole.qt
	# the remote side was cleaned up
	[ ! -e "$BATS_TEST_TMPDIR/remote/p.qt" ]
	# the same jobs' standard outputs, brought back by ssh, in order
	rm tree.qt
	page 'parallel -k --sshloginfile' | sed "s/-s 3/-s 1/;
	    s|parallel --will-cite |&$ssh |" > streams.sh
	[ "$(wc -l < streams.sh)" -eq 3 ]
	bash streams.sh
	cmp tree.qt whole.qt
}

@test "qtstats(1): the map-reduce over ssh, each shard's sums made there, merged here" {
	need_parallel
	start_sshd
	polyread "$SAMPLES/amoeba.brep" > p.qt
	qtsplit -l 8 p.qt | qtstats | grep -v '^max_level_jump ' > want.txt
	qtsplit -l 8 -t 1 p.qt | qtstats -s > top.sums
	echo 2/qtree-test > hosts
	ssh="--ssh 'ssh -F $BATS_TEST_TMPDIR/ssh/ssh.cfg' --env PATH"
	ssh="$ssh --wd '$BATS_TEST_TMPDIR/remote'"
	example "$TOP/man/qtstats.1" 'figures.txt' | commands |
	    sed "s/-l 16/-l 8/g; s/-s 3/-s 1/; s|parallel |parallel --will-cite $ssh |" \
	    > recipe.sh
	[ "$(wc -l < recipe.sh)" -eq 4 ]
	bash recipe.sh
	cmp figures.txt want.txt
	[ ! -e "$BATS_TEST_TMPDIR/remote/p.qt" ]
}
