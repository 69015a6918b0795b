/**
 * Light from an environment, on the CPU and without OpenGL: Radiance {@code .hdr} files ({@link RadianceHdr}),
 * equirectangular maps ({@link LatLongMap}), a procedural clear sky ({@link ClearSky}), the few extended lights a
 * map is reduced to for the diffraction shaders ({@link MedianCut}, {@link ExtendedLight}) and its diffuse irradiance
 * for the pigment ({@link ShIrradiance}). Units: a map holds radiance in units of the key light, so that a light of
 * power P (the integral of radiance over its solid angle) delivers irradiance P to a surface facing it, as the key
 * light delivers 1.
 */
package diffract.lighting;
