// A polygon instance's transform and colour: from per-instance attributes (GpuScene's groups), or
// with PLANT_INDEX from the plants resident on the GPU (the GPU sampler's, plant_instances.glsl),
// by the plant index that is the instance's one attribute: 4 bytes a polygon plant, where a copy
// of its transform, normal matrix and colour would take 112.
#ifdef PLANT_INDEX
layout(location = 3) in uint plant;
#include "plant_instances.glsl"

mat4 instance_model() { return instance_model(plant); }
// transpose(inverse(m)) up to a positive factor, which the normal's normalization takes out: its
// cofactors, signed by the determinant (cheaper per vertex than the inverse).
mat3 instance_normal_matrix() {
  mat3 m = mat3(instance_model(plant));
  mat3 cofactors = mat3(cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1]));
  return dot(m[0], cofactors[0]) < 0.0 ? -cofactors : cofactors;
}
vec3 instance_color() { return instance_tint(plant); }
#else
layout(location = 3) in mat4 model;
layout(location = 7) in mat3 normal_matrix;  // mat3(transpose(inverse(model)))
layout(location = 10) in vec3 color;

mat4 instance_model() { return model; }
mat3 instance_normal_matrix() { return normal_matrix; }
vec3 instance_color() { return color; }
#endif
