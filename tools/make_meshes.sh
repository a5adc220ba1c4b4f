#!/usr/bin/env bash
# Regenerates every committed mesh (testcases/*.med and testcases/meshes/*.med)
# with lunaster-meshgen. Usage: tools/make_meshes.sh [path/to/lunaster-meshgen]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
gen="${1:-$root/build/lunaster-meshgen}"
tc="$root/testcases"
m="$tc/meshes"
mkdir -p "$m"

# SSNP121 modelisations (A, B, C, G share ssnp121a.med)
"$gen" --upper quad4:12 --lower quad4:11 -o "$tc/ssnp121a.med"
"$gen" --upper quad4:12 --lower quad8:11 -o "$tc/ssnp121h.med"
# SSNP121 A refined (ssnp121a_fine.lua: contact passes on the kept elastic factorisation)
"$gen" --upper quad4:48 --lower quad4:44 -o "$m/ssnp121a_fine.med"
"$gen" --v1 hexa20:4x4x4 --v2 hexa20:4x4x4 -o "$tc/ssnp121d.med"
"$gen" --v1 penta15:4x4x4 --v2 penta15:4x4x4 -o "$tc/ssnp121e.med"
"$gen" --v1 penta15:4x4x4 --v2 hexa20:4x4x4 -o "$tc/ssnp121f.med"
"$gen" --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 -o "$tc/ssnp121i.med"
"$gen" --v1 penta6:4x4x4 --v2 penta15:4x4x4 -o "$tc/ssnp121j.med"
"$gen" --v1 penta6:4x4x4 --v2 hexa20:4x4x4 -o "$tc/ssnp121k.med"
# Incompatible pairings the seed warns about (decks assert the warning): QUAD8 slave on TRIA6
# master (F with the roles swapped) and QUAD4 slave on TRIA6 master (K variant)
"$gen" --v1 hexa20:4x4x4 --v2 penta15:4x4x4 -o "$tc/ssnp121f_quad8_on_tria6.med"
"$gen" --v1 hexa8:4x4x4 --v2 penta15:4x4x4 -o "$tc/ssnp121k_quad4_on_tria6.med"

# Pressurised ring in a sleeve (mortar contact on a curved non-matching interface, Lame solution)
"$gen" --ring quad4:96x16 --sleeve quad4:80x16 -o "$tc/ring_sleeve_mortar.med"
"$gen" --ring quad8:48x8 --sleeve quad8:40x8 -o "$tc/ring_sleeve_mortar_quad8.med"

# Hertz contact: cylinder on block (D_PLAN), sphere on block (3D quarter model and AXIS)
"$gen" --hertz quad8:400 --grading 1.1 -o "$tc/hertz_cylinder_dplan.med"
"$gen" --hertz hexa20:80 --grading 1.5 -o "$tc/hertz_sphere_3d.med"
"$gen" --hertz quad8:160 --grading 1.5 -o "$tc/hertz_sphere_axis.med"
"$gen" --hertz hexa20:20 --grading 1.5 -o "$tc/meshes/hertz_sphere_3d_coarse.med"
# Coulomb friction: the frictional patch tests (2D matching blocks, 3D cubes with their sides as
# groups) and Cattaneo's cylinder (the whole scene: a load along x).
"$gen" --upper quad4:8 --lower quad4:8 -o "$tc/friction_patch_2d.med"
"$gen" --v1 hexa8:4x4x4 --v2 hexa8:4x4x4 --x-faces -o "$tc/friction_patch_3d.med"
"$gen" --hertz quad4:400 --grading 1.1 --full -o "$tc/cattaneo_cylinder.med"

# The README's first deck (testcases/first_deck.lua): a unit square of 4 x 4 QUAD4
"$gen" --block quad4:4 -o "$tc/first_deck.med"

# Glued (conforming) versions: both blocks share the interface nodes
"$gen" --upper quad4:4 --lower quad4:4 --glued -o "$m/glued2d_quad4.med"
"$gen" --upper quad8:4 --lower quad8:4 --glued -o "$m/glued2d_quad8.med"
"$gen" --v1 hexa8:3x3x3 --v2 hexa8:3x3x3 --glued -o "$m/glued3d_hexa8.med"
"$gen" --v1 hexa20:2x2x2 --v2 hexa20:2x2x2 --glued -o "$m/glued3d_hexa20.med"

# Non-matching 3D interface of different cell types and sizes (mortar_bimaterial_3d.lua)
"$gen" --v1 penta6:5x5x2 --v2 hexa20:3x3x2 -o "$m/nonmatching3d_penta6_hexa20.med"
# LIAISON_MAIL's scenes (liaison_mail.lua): nested interfaces (the slave face is the master face refined
# twice), and nodes that match under faces that do not
"$gen" --v1 hexa8:8x8x2 --v2 hexa8:4x4x2 -o "$m/liaison_mail_nested3d.med"
"$gen" --upper quad4:16 --lower quad4:8 -o "$m/liaison_mail_nested2d.med"
"$gen" --v1 tetra4:4x4x2 --v2 tetra10:2x2x2 -o "$m/liaison_mail_tetra.med"
# Three stacked blocks, two non-matching interfaces (mortar_two_zones_2d.lua, mortar_two_zones_3d.lua)
"$gen" --upper quad4:12 --lower quad4:11 --top tria6:5 -o "$m/mortar_two_zones_2d.med"
"$gen" --v1 hexa8:5x5x2 --v2 hexa20:3x3x2 --v3 penta6:4x4x2 -o "$m/mortar_two_zones_3d.med"

# A unit block of 12^3 HEXA8, fronts large enough for MUMPS's block low-rank compression
# (testcases/errors/mumps_low_rank_too_coarse.lua)
"$gen" --block hexa8:12 -o "$m/block_hexa8_12.med"

# Distorted unit blocks for patch tests
for t in quad4 quad8 tria3 tria6; do
  "$gen" --block "$t:3" --distort 0.2 -o "$m/patch_$t.med"
done
for t in hexa8 hexa20 penta6 penta15 tetra4 tetra10; do
  "$gen" --block "$t:2" --distort 0.15 -o "$m/patch_$t.med"
done
# The same in code_aster's text format, for the quadratic 3D cells (testcases/aster_mail.lua)
for t in hexa20 penta15 tetra10; do
  "$gen" --block "$t:2" --distort 0.15 -o "$m/patch_$t.mail"
done
"$gen" --upper quad4:12 --lower quad4:11 -o "$m/ssnp121a.mail"

# Axisymmetric (AXIS, x = r) patch tests away from the axis: distorted blocks [1,2]x[0,1]. The
# patch_*.med blocks above ([0,1]^2, LEFT on x = 0) are the patches touching the axis.
for t in quad4 quad8 tria3 tria6; do
  "$gen" --block "$t:3" --distort 0.2 --rect 1,2,0,1 -o "$m/axis_patch_$t.med"
done
# Thick-walled cylinder a = 1 <= r <= b = 2 (AXIS, Lame), one cell high, NR cells through the wall
"$gen" --block quad8:96x1 --rect 1,2,0,0.0625 -o "$m/axis_cylinder_quad8.med"
"$gen" --block quad4:128x1 --rect 1,2,0,0.0078125 -o "$m/axis_cylinder_quad4.med"

# Axisymmetric contact patch tests (AXIS, x = r): the SSNP121 blocks on 0 <= r <= 1 (touching the
# axis), matching and non-matching, and non-matching on 1 <= r <= 2; QUAD8 non-matching on the axis
"$gen" --upper quad4:8 --lower quad4:8 --x-range 0,1 -o "$m/axis_contact_matching.med"
"$gen" --upper quad4:12 --lower quad4:11 --x-range 0,1 -o "$m/axis_contact_nonmatching.med"
"$gen" --upper quad4:12 --lower quad4:11 --x-range 1,2 -o "$m/axis_contact_nonmatching_away.med"
"$gen" --upper quad8:5 --lower quad8:4 --x-range 0,1 -o "$m/axis_contact_nonmatching_quad8.med"

# One-cell unit blocks (testcases/loads_and_groups.lua names their nodes N1..N4 / cell M5)
"$gen" --block quad4:1 -o "$m/unit_quad4.med"
"$gen" --block hexa8:1 -o "$m/unit_hexa8.med"
# Orientation: the same scenes meshed clockwise (--mirror: cells and boundary edges of a block
# listed as Gmsh writes a surface meshed from a clockwise curve loop), in MED and Gmsh 2.2 / 4.1.
# The counter-clockwise MED blocks are patch_quad8.med and patch_tria6.med above.
for t in quad8 tria6; do
  "$gen" --block "$t:3" --distort 0.2 --mirror BLOCK -o "$m/patch_${t}_cw.med"
  for v in 2.2 4.1; do
    "$gen" --block "$t:3" --distort 0.2 --msh-version "$v" -o "$m/patch_${t}_v${v/./}.msh"
    "$gen" --block "$t:3" --distort 0.2 --mirror BLOCK --msh-version "$v" -o "$m/patch_${t}_cw_v${v/./}.msh"
  done
done
# Boundary cells pointing into their body (AFFE_CHAR_MECA VERI_NORM, testcases/veri_norm_*.lua and
# testcases/errors/veri_norm_*.lua): the thick cylinder and a 3D block meshed mirrored.
"$gen" --block quad8:96x1 --rect 1,2,0,0.0625 --mirror BLOCK -o "$m/axis_cylinder_quad8_cw.med"
"$gen" --block penta6:2 --distort 0.15 --mirror BLOCK -o "$m/patch_penta6_cw.med"
# Two-block contact scene (SSNP121 geometry, non-matching QUAD4 / TRIA3): counter-clockwise, the
# lower (master) block clockwise, the upper (slave) block clockwise.
for variant in ccw cw_master cw_slave; do
  mirror=()
  [ "$variant" = cw_master ] && mirror=(--mirror PLAQUE2)
  [ "$variant" = cw_slave ] && mirror=(--mirror PLAQUE1)
  "$gen" --upper quad4:6 --lower tria3:4 "${mirror[@]}" -o "$m/contact2d_$variant.med"
  for v in 2.2 4.1; do
    "$gen" --upper quad4:6 --lower tria3:4 "${mirror[@]}" --msh-version "$v" -o "$m/contact2d_${variant}_v${v/./}.msh"
  done
done
