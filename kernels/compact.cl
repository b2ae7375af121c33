/* compact_*: stable stream compaction of fixed-size records on the device, in three launches.
 * Each work-item owns a chunk of `chunk` consecutive slots (measured fastest on PoCL: no
 * barriers, no contended atomics): compact_count counts its kept slots, compact_scan turns the
 * counts into chunk offsets and the total, compact_scatter copies the kept records in order.
 * Records are moved as `words` uint4s, so one kernel serves rays and shadow rays alike. Records
 * past `capacity` are counted but not written, so the host can detect an overflow safely. Only
 * the total crosses to the host. */

__kernel void compact_count(__global const uint* flags, uint n, uint chunk,
                            __global uint* chunk_counts) {
  const uint c = get_global_id(0);
  const uint begin = c * chunk;
  if (begin >= n) return;
  const uint end = min(begin + chunk, n);
  uint kept = 0;
  for (uint i = begin; i < end; ++i) kept += flags[i] != 0u;
  chunk_counts[c] = kept;
}

/* One work-item: the chunk count is small (n / chunk), so a serial scan costs microseconds. */
__kernel void compact_scan(__global uint* chunk_counts, uint chunks, __global uint* total) {
  if (get_global_id(0) != 0) return;
  uint sum = 0;
  for (uint c = 0; c < chunks; ++c) {
    const uint kept = chunk_counts[c];
    chunk_counts[c] = sum;
    sum += kept;
  }
  *total = sum;
}

__kernel void compact_scatter(__global const uint4* in, __global const uint* flags, uint n,
                              uint chunk, uint words, __global const uint* chunk_offsets,
                              __global uint4* out, uint capacity) {
  const uint c = get_global_id(0);
  const uint begin = c * chunk;
  if (begin >= n) return;
  const uint end = min(begin + chunk, n);
  uint to = chunk_offsets[c];
  for (uint i = begin; i < end && to < capacity; ++i) {
    if (flags[i] == 0u) continue;
    const size_t from = (size_t)i * words, into = (size_t)to * words;
    for (uint w = 0; w < words; ++w) out[into + w] = in[from + w];
    ++to;
  }
}
