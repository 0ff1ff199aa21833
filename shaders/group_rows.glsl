// Passes with more work groups than GL guarantees in one dimension (65535) lay them in rows: the
// indirect dispatch command for `groups`, and the number of the group running.
uvec4 group_rows(uint groups) {
  const uint row = 65535u;
  return groups == 0u ? uvec4(0u, 1u, 1u, 0u) : uvec4(min(groups, row), (groups + row - 1u) / row, 1u, 0u);
}

uint group_number() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }
