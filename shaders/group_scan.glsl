// Sums over a work group of 256 threads (local_size_x = 256): Hillis and Steele's scan in shared
// memory. Every thread of the group calls it (it holds barriers), and may call it again at once.
shared uint scan_sums[256];

// `own` added to the values of the threads before this one (inclusive); `total` the whole group's.
uint inclusive_sum(uint own, out uint total) {
  uint t = gl_LocalInvocationID.x;
  scan_sums[t] = own;
  barrier();
  for (uint step = 1u; step < 256u; step *= 2u) {
    uint before = t >= step ? scan_sums[t - step] : 0u;
    barrier();
    scan_sums[t] += before;
    barrier();
  }
  uint sum = scan_sums[t];
  total = scan_sums[255];
  barrier();
  return sum;
}
