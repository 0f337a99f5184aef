// tile_run.glsl: how both compute shaders share out a band's pixels among invocations. Each
// workgroup takes a run of adjacent 8x8 tiles, and each lane the same pixel of each tile in
// turn, so that the lanes of a vector stay near each other; the runs are visited in a
// scattered order (params.tileOrderStride), so that each of lavapipe's threads (which take
// contiguous runs of workgroups) gets a share of every part of the band. The shader's own
// setPixel(tile) says whether the lane's pixel of a tile lies in the band. Include after the
// push constants and params are declared.

uint tile;       // the tile of the band (row by row) whose pixel the lane computes
uint runEnd;     // the end of the lane's run of tiles
uint bandRows;   // rows of this band (the last may be short)

// The first tile of this workgroup's run; sets runEnd and bandRows.
uint startRun() {
  uint runs = gl_NumWorkGroups.x;
  uint tilesPerRun = (params.tilesX * (params.bandHeight / kWorkgroupSize) + runs - 1u) / runs;
  bandRows = min(params.bandHeight, params.height - pc.bandY0);
  uint bandTiles = params.tilesX * ((bandRows + kWorkgroupSize - 1u) / kWorkgroupSize);
  uint runStart = (gl_WorkGroupID.x * params.tileOrderStride) % runs * tilesPerRun;
  runEnd = min(runStart + tilesPerRun, bandTiles);
  return runStart;
}

bool setPixel();   // the shader's: whether the lane's pixel of `tile` lies in the band (and sets it)

// The lane's last pixel of its run (tile and the shader's pixel set to it); false when none
// of the run's tiles has one.
bool lastPixelOfRun(uint runStart) {
  tile = runEnd;
  bool found = false;
  while (tile > runStart && !found) {
    --tile;
    found = setPixel();
  }
  return found;
}

// The lane's first pixel of its run (lastPixelOfRun found one).
void firstPixelOfRun(uint runStart) {
  tile = runStart;
  while (!setPixel()) ++tile;
}
