// One cube-map array lookup shared by the methods that keep probes (included once; the includer
// has common.glsl's frame block).
// Cube `layer` of a cube-map array (a method's probes) along `direction`: rgb filtered by the
// footprint (dx, dy) when mip-mapping is on, else level 0; alpha always level 0's (probes keep
// the distance to what they saw there).
vec4 probe_radiance(samplerCubeArray probes, vec3 direction, float layer, vec3 dx, vec3 dy) {
  vec4 coords = vec4(direction, layer);
  vec4 level0 = textureLod(probes, coords, 0.0f);
  vec3 color = frame.options.y != 0 ? textureGrad(probes, coords, dx, dy).rgb : level0.rgb;
  return vec4(color, level0.a);
}

// The scene's distant environment along `direction`, filtered by the footprint (dx, dy) when
// mip-mapping is on, else level 0: reflection.glsl's environment_radiance, and what a scene's
// blended probes leave (probe_lookup.glsl, in passes without reflection.glsl too).
vec3 environment_lookup(vec3 direction, vec3 dx, vec3 dy) {
  if (frame.options.y != 0) return textureGrad(u_environment, direction, dx, dy).rgb;
  return textureLod(u_environment, direction, 0.0f).rgb;
}
