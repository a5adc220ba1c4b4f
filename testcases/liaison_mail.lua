-- Gluing meshes that do not match (AFFE_CHAR_MECA LIAISON_MAIL, TYPE_RACCORD = 'MASSIF', code_aster's
-- gluing): each slave node follows the master cell that holds it, u(node) = sum_a N_a(xi) u_a for each
-- DDL, one linear relation each.
-- Purpose: the ties on the scenes where they are exact, each solved twice: a Lagrange multiplier per
--          relation (SOLVEUR ELIM_LAGR = 'NON', the default) and each relation solved for its slave
--          unknown (ELIM_LAGR = 'OUI': no multipliers, an SPD system for CHOLMOD); and, for the record,
--          two scenes where they are not.
-- Scenes (two blocks of unit height, E1 below, E2 above, NU = 0; bottom clamped, top DZ (DY) = -0.1 with
--          DX = DY = 0):
--   1. 3D, V1 = [0,1]^3 HEXA8 8x8x2 under V2 = [0,1]^2 x [1,2] HEXA8 4x4x2 (liaison_mail_nested3d.med):
--      slave nodes those of V1's top face SURESC, master cells V2's. E1 = 6e6 Pa, E2 = 2e6 Pa.
--      The clamped bottom nodes ENCAST are slave nodes too (GROUP_NO_ESCL), with DISTANCE_MAX = 0.5 m:
--      they lie 1 m from V2, so it leaves them free (without it they would follow V2's bottom face).
--   2. 2D plane strain, PLAQUE1 = [-1,1]x[0,1] QUAD4 16x16 (slave nodes: those of AB, its bottom
--      edge) on PLAQUE2 = [-1,1]x[-1,0] QUAD4 8x8 (master cells) (liaison_mail_nested2d.med), E2 = 2e6 Pa
--      above, E1 = 6e6 Pa below; the end nodes A and B tied by a first occurrence (DDL DX, DY), which
--      ELIM_MULT = 'OUI' then leaves out of the second (GROUP_MA_ESCL = 'AB').
--   3. 3D, HEXA20 4x4x4 on HEXA20 4x4x4 (ssnp121d.med), the interface nodes doubled: each slave node
--      (SURESC) coincides with a node of V2, and follows it alone. E1 = E2 = 2e6 Pa.
--   4. 3D, PENTA6 5x5x2 under HEXA20 3x3x2 (nonmatching3d_penta6_hexa20.med, TRIA3 slave faces of side
--      0.2 on QUAD8 master faces of side 1/3): not nested. E1 = 6e6 Pa, E2 = 2e6 Pa.
--   5. 2D, two unit squares, one QUAD4 each, the upper one 1e-3 m above the lower one
--      (liaison_mail_gap_v22.msh): the upper square's bottom nodes lie outside the lower cell and
--      follow the nearest point of its top edge (a rigid link across the gap); DISTANCE_ALARME =
--      1e-4 m warns about both. E1 = E2 = 2e6 Pa.
--   6. Scene 1 the other way round: the nodes of V2's coarse bottom face SURMAI follow V1's fine cells.
--   7. 3D, TETRA4 4x4x2 under TETRA10 2x2x2 (liaison_mail_tetra.med): each slave node (SURESC) lies on
--      a master node, but under TRIA6 master faces where the slave faces are TRIA3. E1 = E2 = 2e6 Pa.
-- Reference: analytical, springs in series: p = 0.1 / (1/E1 + 1/E2), SIZZ (SIYY) = -p in both blocks,
--          DZ (DY) = -p/E1 on the interface, both sides (1.5e5 Pa and 0.025 m; scenes 3 and 5: 1e5 Pa,
--          0.05 m).
-- Why exact (scenes 1 to 3 and 5, checks at 1e-10): the linear field meets every tie (a master cell's
--          shape functions reproduce it), and the forces a slave node passes to the master nodes,
--          weighted by N_a, are the master face's own nodal forces of the uniform traction: nested
--          meshes on linear master cells (each N_a is linear on every slave face, which the slave's
--          nodal forces integrate exactly), or matching faces (coincident nodes alone are not enough:
--          scene 7).
-- Scenes 4, 6 and 7: not exact, checked by VALE_CALC only (non-regression). Scene 4: passed through N_a,
--          the slave forces are not the quadratic master face's nodal forces: node-to-cell ties fail
--          the patch test, as node-to-segment contact does (mortar contact on this mesh is exact to
--          1e-13: testcases/mortar_bimaterial_3d.lua). Scene 6: the fine face's nodes between the
--          coarse face's are free, so its forces there go nowhere: choose the finer side as slave.
--          Scene 7: the nodes match, the faces do not: a TRIA6 face takes a uniform traction on its
--          mid-side nodes only, the TRIA3 faces on their vertices.
-- What we get: scenes 1 to 3 and 5 within 2e-14 of the analytical values (relative), both ways of
--          solving; scene 4 (both ways alike): DZ on the slave face from -0.0259 to -0.0223 m (up to
--          11 % off), SIZZ from -1.63e5 to -1.17e5 Pa (up to 22 % off); scene 6: DZ from -0.0285 to
--          -0.0219 m (14 % off), SIZZ from -2.09e5 to -1.15e5 Pa (39 % off); scene 7: DZ from -0.0512 to
--          -0.0460 m (8 % off), SIZZ from -1.01e5 to -8.64e4 Pa (14 % off).
-- Runtime label: fast.
DEBUT()
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- One glued block pair: materials, loads (with the LIAISON_MAIL occurrences `ties`), both solves.
local function scene(name, file, dim, E1, E2, ties, checks)
  local gmsh = file:match('%.msh$') ~= nil
  local MA = LIRE_MAILLAGE{ FORMAT = gmsh and 'GMSH' or 'MED', FICHIER = file }
  local low, high = dim == 3 and 'V1' or 'PLAQUE2', dim == 3 and 'V2' or 'PLAQUE1'
  if gmsh then low, high = 'LOWER', 'UPPER' end
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE',
                                                    MODELISATION = dim == 3 and '3D' or 'D_PLAN' } }
  local M1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = 0.0 } }
  local M2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = 0.0 } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = low, MATER = M1 },
                                                    _F{ GROUP_MA = high, MATER = M2 } } }
  local CH
  if dim == 3 then
    CH = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_MAIL = ties,
                         DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                      _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
  else
    local top, bottom = gmsh and 'TOP' or 'CD', gmsh and 'BOTTOM' or 'GH'
    CH = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_MAIL = ties,
                         DDL_IMPO = { _F{ GROUP_NO = top, DX = 0.0, DY = -0.1 },
                                      _F{ GROUP_NO = bottom, DX = 0.0, DY = 0.0 } } }
  end
  for _, elim in ipairs({ 'NON', 'OUI' }) do
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                             SOLVEUR = _F{ ELIM_LAGR = elim } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
    TEST_RESU{ RESU = checks(R, name .. ', ELIM_LAGR ' .. elim) }
  end
end

-- Springs in series: the interface displacement and the stress of the analytical solution.
local function series(E1, E2)
  local p = 0.1 / (1.0 / E1 + 1.0 / E2)
  return -p / E1, -p
end

-- Exact checks: the component `u` on the slave and master sides of the interface, and the stress
-- `s` on every node (MIN and MAX).
local function exact(E1, E2, u, s, slave, master)
  local d, sigma = series(E1, E2)
  return function(R, legend)
    local out = {}
    local function add(cham, cmp, group, refe)
      for _, kind in ipairs({ 'MIN', 'MAX' }) do
        out[#out + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                            GROUP_NO = group, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10,
                            LEGENDE = legend }
      end
    end
    add('DEPL', u, slave, d)
    add('DEPL', u, master, d)
    add('SIGM_NOEU', s, slave, sigma)
    add('SIGM_NOEU', s, master, sigma)
    return out
  end
end

scene('nested 3D', 'meshes/liaison_mail_nested3d.med', 3, 6.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC', GROUP_NO_ESCL = 'ENCAST', DISTANCE_MAX = 0.5,
            TYPE_RACCORD = 'MASSIF' } },
      exact(6.0e6, 2.0e6, 'DZ', 'SIZZ', 'SURESC', 'SURMAI'))
scene('nested 2D', 'meshes/liaison_mail_nested2d.med', 2, 6.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_NO_ESCL = { 'A', 'B' }, DDL = { 'DX', 'DY' } },
        _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_MA_ESCL = 'AB', ELIM_MULT = 'OUI' } },
      exact(6.0e6, 2.0e6, 'DY', 'SIYY', 'AB', 'EF'))
scene('coincident HEXA20', 'ssnp121d.med', 3, 2.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC' } },
      exact(2.0e6, 2.0e6, 'DZ', 'SIZZ', 'SURESC', 'SURMAI'))

-- Scenes 4 and 6: non-regression only (VALE_CALC from a real run, relative 1e-6), the same both ways.
local function recorded(calc)
  return function(R, legend)
    local out = {}
    for _, key in ipairs({ 'DEPL DZ MIN', 'DEPL DZ MAX', 'SIGM_NOEU SIZZ MIN', 'SIGM_NOEU SIZZ MAX' }) do
      local cham, cmp, kind = key:match('(%S+) (%S+) (%S+)')
      out[#out + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                          GROUP_NO = 'SURESC', VALE_CALC = calc[key], LEGENDE = legend }
    end
    return out
  end
end
scene('PENTA6 under HEXA20', 'meshes/nonmatching3d_penta6_hexa20.med', 3, 6.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC' } },
      recorded({ ['DEPL DZ MIN'] = -2.591553279e-02, ['DEPL DZ MAX'] = -2.234004834e-02,
                 ['SIGM_NOEU SIZZ MIN'] = -1.627336469e+05, ['SIGM_NOEU SIZZ MAX'] = -1.168023398e+05 }))

-- Scene 5: a gap of 1e-3 m between the squares; its two slave nodes are tied from outside the cell.
scene('gap', 'meshes/liaison_mail_gap_v22.msh', 2, 2.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'LOWER', GROUP_MA_ESCL = 'UPPER_BOTTOM', DISTANCE_ALARME = 1.0e-4 } },
      exact(2.0e6, 2.0e6, 'DY', 'SIYY', 'UPPER_BOTTOM', 'LOWER_TOP'))

-- Scene 6: scene 1's mesh glued the other way round, the coarse face's nodes (SURMAI) following the
-- fine block's cells: the fine face's nodes between them are free, and the interface no longer
-- carries the uniform traction.
scene('coarse side as slave', 'meshes/liaison_mail_nested3d.med', 3, 6.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'V1', GROUP_MA_ESCL = 'SURMAI' } },
      recorded({ ['DEPL DZ MIN'] = -2.848085082e-02, ['DEPL DZ MAX'] = -2.191035284e-02,
                 ['SIGM_NOEU SIZZ MIN'] = -2.085751133e+05, ['SIGM_NOEU SIZZ MAX'] = -1.147363574e+05 }))

-- Scene 7: coincident nodes under faces of different orders.
scene('TETRA4 under TETRA10', 'meshes/liaison_mail_tetra.med', 3, 2.0e6, 2.0e6,
      { _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC' } },
      recorded({ ['DEPL DZ MIN'] = -5.116997068e-02, ['DEPL DZ MAX'] = -4.595887702e-02,
                 ['SIGM_NOEU SIZZ MIN'] = -1.014807999e+05, ['SIGM_NOEU SIZZ MAX'] = -8.636838826e+04 }))
FIN()
