#!/usr/bin/env bats
# qtmesh -f inp: the Abaqus/CalculiX deck, its sets and surfaces by ring
# edge, read by CalculiX itself where it is installed.

load test_helper

@test "-f inp: each ring edge's node set lies on that edge, by coordinates" {
	run bash -c 'qtsplit -l 6 "$SAMPLES/quarter-plate.qt" | qtbalance |
	    qtmesh -b -f inp > mesh.inp &&
	    awk -F", *" "/^\\*/ { set = \"\"; if (\$0 ~ /^\\*NODE,/) mode = \"n\";
	        else if (\$1 == \"*NSET\") { mode = \"s\"; sub(/NSET=/, \"\", \$2); set = \$2 }
	        else mode = \"\"; next }
	        mode == \"n\" { x[\$1] = \$2; y[\$1] = \$3 }
	        mode == \"s\" { for (i = 1; i <= NF; i++) if (\$i != \"\") {
	            n = \$i; bad = 0
	            if (set == \"R1E1\" && y[n] != 0) bad = 1
	            if (set == \"R1E2\" && x[n] != 1) bad = 1
	            if (set == \"R1E3\" && y[n] != 1) bad = 1
	            if (set == \"R1E4\" && x[n] != 0) bad = 1
	            d = 0.01 - x[n]^2 - y[n]^2
	            if (set == \"R1E5\" && (d < -1e-15 || d > 1 / 64^2 / 4)) bad = 1
	            if (bad) { print set, n, x[n], y[n]; exit 1 }
	            seen[set]++ } }
	        END { for (s in seen) print s, seen[s] }" mesh.inp | sort'
	[ "$status" -eq 0 ]
	[ "${lines[0]%% *}" = R1 ]
	[ "${lines[1]%% *}" = R1E1 ]
	[ "${lines[5]%% *}" = R1E5 ]
	[ "${#lines[@]}" -eq 6 ]
}

@test "-f inp: CalculiX solves the plate, the reaction balances the load" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	qtsplit -l 7 "$SAMPLES/quarter-plate.qt" | qtbalance |
	    qtmesh -b -f inp > mesh.inp
	cat > plate.inp <<-'DECK'
	*INCLUDE, INPUT=mesh.inp
	*MATERIAL, NAME=M
	*ELASTIC
	1000., 0.3
	*SOLID SECTION, ELSET=EALL, MATERIAL=M
	1.
	*STEP
	*STATIC
	*BOUNDARY
	R1E1, 2
	R1E4, 1
	*DSLOAD
	R1E2, P, -1.
	*NODE PRINT, NSET=R1E4, TOTALS=ONLY
	RF
	*END STEP
	DECK
	run ccx plate
	[ "$status" -eq 0 ]
	# the load is 1 on the side x = 1 of length 1: the supports at x = 0
	# give it back (a face taken wrongly would give another total)
	run awk '/total force/ { getline; getline; print $1 }' plate.dat
	[ "$status" -eq 0 ]
	awk -v f="$output" 'BEGIN { exit !(f + 1 < 1e-9 && f + 1 > -1e-9) }'
}

@test "-e without -f inp, -f inp with -H and an unknown family are refused" {
	run qtmesh -e CPS < /dev/null
	[ "$status" -eq 2 ]
	run qtmesh -H -f inp < /dev/null
	[ "$status" -eq 2 ]
	run qtmesh -f inp -e XYZ < /dev/null
	[ "$status" -eq 2 ]
	[[ "$output" == *"unknown element family XYZ"* ]]
}

# Kt of the quarter plate at level $1 with qtmesh options $2: nodal sigma_xx
# at the top of the hole, (0, 0.1), in CalculiX's .frd; or of plate $3
# with the top of its hole at (0, $4), of thickness $5 (CalculiX makes the
# plane elements solids that thick: keep it in scale).
plate_kt() {
	qtsplit -l "$1" "${3:-$SAMPLES/quarter-plate.qt}" | qtbalance |
	    qtmesh -b $2 -f inp > mesh.inp
	cat > plate.inp <<-DECK
	*INCLUDE, INPUT=mesh.inp
	*MATERIAL, NAME=M
	*ELASTIC
	1000., 0.3
	*SOLID SECTION, ELSET=EALL, MATERIAL=M
	${5:-1.}
	*STEP
	*STATIC
	*BOUNDARY
	R1E1, 2
	R1E4, 1
	*DSLOAD
	R1E2, P, -1.
	*EL FILE
	S
	*END STEP
	DECK
	ccx plate > ccx.log 2>&1 || return 1
	awk -v top="${4:-0.1}" '/^\*/ { innode = $0 ~ /^\*NODE,/; next }
	    innode { split($0, f, /, */); if (f[2] == 0 && f[3] == top) id = f[1] }
	    END { while ((getline line < "plate.frd") > 0)
	        if (substr(line, 1, 3) == " -4") { split(line, w, " "); s = w[2] == "STRESS" }
	        else if (s && substr(line, 1, 3) == " -1" && substr(line, 4, 10) + 0 == id) {
	            print substr(line, 14, 12) + 0; exit } exit 1 }' mesh.inp
}

# Kt with qtmesh options $1 at the levels $3 ...: its error against 3.1068
# non-increasing with the level and under $2 % at the last.
converges() {
	local opts=$1 bound=$2 last=100 l kt err
	shift 2
	for l; do
		kt=$(plate_kt "$l" "$opts")
		err=$(awk -v k="$kt" 'BEGIN { e = (k - 3.1068) / 3.1068; print 100 * (e < 0 ? -e : e) }')
		echo "level $l: Kt $kt, error $err %"
		awk -v e="$err" -v p="$last" 'BEGIN { exit !(e <= p) }' || return 1
		last=$err
	done
	awk -v e="$err" -v b="$bound" 'BEGIN { exit !(e < b) }'
}

@test "CalculiX on the plate: Kt converges on 3.1068 with the level, linear" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	# 3.1068: Gmsh's second-order meshes of the same plate solved by ccx
	# (tools/bench/benchkt.sh; 3.1064, 3.1068, 3.1069 at 39k, 154k and
	# 605k nodes); Peterson's finite-width chart gives about 3.1 for
	# d/W = 0.1, and an infinite plate 3
	converges -T 0.5 9 10 11
}

@test "CalculiX on the plate: Kt converges on 3.1068 with the level, second order" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	converges -2 0.1 8 9 10
}

@test "CalculiX solves the second-order deck of the plate in millimetres and in metres" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	# the plate scaled by 1000 and by 1/1024 (exact in binary): the same
	# Kt to 1e-4 (the stress does not change with the plate's size)
	kt=$(plate_kt 9 "-2 -T")
	for s in 1000 0.0009765625; do
		awk -v s="$s" 'function sc(v) { return sprintf("%.17g", v * s) }
		    $1 == "universe" { $2 = sc($2); $3 = sc($3); $4 = sc($4) }
		    $1 == "v" || $1 == "a" { $2 = sc($2); $3 = sc($3) } { print }' \
		    "$SAMPLES/quarter-plate.qt" > scaled.qt
		# the top of the hole: the lowest vertex on x = 0
		top=$(awk '$1 == "v" && $2 == 0 && (t == "" || $3 < t) { t = $3 }
		    END { print t }' scaled.qt)
		k=$(plate_kt 9 "-2 -T" scaled.qt "$top" "$s")
		echo "scale $s: Kt $k against $kt"
		awk -v a="$k" -v b="$kt" 'BEGIN { d = a - b; exit !(d < 1e-4 && d > -1e-4) }'
	done
}

@test "-f inp: every coordinate fits CalculiX's 20-character field and is the mesh's to 5e-16" {
	# the plate at 1/1024 of its size: shortest digits of 17 and an
	# exponent make 21 characters, which ccx refuses ("ERROR reading *NODE")
	awk 'function sc(v) { return sprintf("%.17g", v / 1024) }
	    $1 == "universe" { $2 = sc($2); $3 = sc($3); $4 = sc($4) }
	    $1 == "v" || $1 == "a" { $2 = sc($2); $3 = sc($3) } { print }' \
	    "$SAMPLES/quarter-plate.qt" > small.qt
	qtsplit -l 8 small.qt | qtbalance > t.qt
	qtmesh -b -2 -f inp t.qt > m.inp
	qtmesh -b -2 -f msh t.qt > m.msh
	run -0 awk -F', ' 'FNR == 1 { file++ }
	    file == 1 && $0 == "$Nodes" { getline; on = 1; next }
	    file == 1 && /^\$End/ { on = 0 }
	    file == 1 && on { split($0, f, " "); x[f[1]] = f[2]; y[f[1]] = f[3] }
	    file == 2 && /^\*/ { on = $0 ~ /^\*NODE,/; next }
	    file == 2 && on { n++
	        if (length($2) > 20 || length($3) > 20) { print "wide:", $0; bad++ }
	        if (length($2) == 20 || length($3) == 20) full++
	        dx = $2 - x[$1]; dy = $3 - y[$1]
	        if (dx * dx + dy * dy > (5e-16 * 0.001) ^ 2) { print "off:", $0; bad++ } }
	    END { print n, full + 0, bad + 0; exit bad > 0 }' m.msh m.inp
	echo "$output"
	set -- ${lines[${#lines[@]} - 1]}
	[ "$1" -gt 100 ]
	[ "$2" -gt 0 ]
}

@test "README: the plate's recipe for CalculiX runs as printed and gives its Kt" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	sed -n '/^    \$ qtsplit -l 10 samples\/quarter-plate.qt/,/^    \$ ccx plate$/p' "$TOP/README" |
	    sed 's/^    //; s/^\$ //; s#samples/#$SAMPLES/#' > recipe.sh
	[ "$(wc -l < recipe.sh)" -gt 15 ]
	SAMPLES=$SAMPLES bash -e recipe.sh > ccx.out
	# sigma_xx at the node at (0, 0.1): the figure README gives, 0.013 %
	kt=$(awk '/^\*/ { innode = $0 ~ /^\*NODE,/; next }
	    innode { split($0, f, /, */); if (f[2] == 0 && f[3] == 0.1) id = f[1] }
	    END { while ((getline line < "plate.frd") > 0)
	        if (substr(line, 1, 3) == " -4") { split(line, w, " "); s = w[2] == "STRESS" }
	        else if (s && substr(line, 1, 3) == " -1" && substr(line, 4, 10) + 0 == id) {
	            print substr(line, 14, 12) + 0; exit } exit 1 }' mesh.inp)
	grep -q "0.013 % from the" "$TOP/README"
	awk -v k="$kt" 'BEGIN { e = 100 * (k - 3.1068) / 3.1068; e = e < 0 ? -e : e
	    printf "Kt %s, %.3f %%\n", k, e; exit !(e > 0.0125 && e < 0.0135) }'
}
