-- Default study sizes (run_study.sh writes its own config.lua next to the decks).
return {
  ks_2d = { 1, 2, 4, 8, 16 },
  max_k_2d = {},
  ks_3d = { 1, 2 },
}
