// examples/engine: the raster path's camera and its CPU ray cast. The camera sits on +z
// looking at the origin with a symmetric perspective (Vulkan clip space: y down, depth 0..1).
// The ray through a pixel centre hits the mesh where the rasterizer samples it, so the
// barycentric interpolation there gives the attributes the fragment shader receives (the
// rasterizer interpolates perspective-correctly, Vulkan spec "Basic Polygon Rasterization").
#pragma once

#include <cmath>
#include <optional>

#include "raster.hpp"

namespace engine {

struct Camera {
  double eye[3] = {0.0, 0.0, 4.0};
  double tanHalfFov = 0.3;  // the unit sphere (silhouette tangent 1/sqrt(15)) fills 86 % of the frame
  double near = 1.0, far = 10.0;

  // engine_vertex.vert's push constants: model = identity, viewProjection, column-major.
  void pushConstants(float out[32]) const {
    for (int i = 0; i < 32; ++i) out[i] = 0.0f;
    for (int i = 0; i < 4; ++i) out[i * 5] = 1.0f;
    float* vp = out + 16;
    const double a = far / (near - far), b = near * far / (near - far);
    vp[0] = float(1.0 / tanHalfFov);       // x_clip = x_view / tan
    vp[5] = float(-1.0 / tanHalfFov);      // y_clip = -y_view / tan (Vulkan's y points down)
    vp[10] = float(a);                     // z_clip = a z_view + b
    vp[11] = -1.0f;                        // w_clip = -z_view
    vp[12] = float(-eye[0] / tanHalfFov);  // view = translation by -eye
    vp[13] = float(eye[1] / tanHalfFov);
    vp[14] = float(-a * eye[2] + b);
    vp[15] = float(eye[2]);
  }
  // The world-space direction through the point (x + 0.5, y + 0.5) of a size x size target
  // (a pixel's centre for whole x, y; Vulkan samples there without multisampling).
  void ray(double x, double y, int size, double dir[3]) const {
    dir[0] = ((x + 0.5) / size * 2.0 - 1.0) * tanHalfFov;
    dir[1] = -((y + 0.5) / size * 2.0 - 1.0) * tanHalfFov;
    dir[2] = -1.0;
  }
};

// What the fragment shader sees at a pixel: the interpolated (not normalized) normal and the
// world position.
struct Hit {
  double position[3], normal[3];
};

// The nearest triangle of `mesh` along eye + t * dir (Moeller-Trumbore).
inline std::optional<Hit> castRay(const Mesh& mesh, const double eye[3], const double dir[3]) {
  auto sub = [](const float* a, const float* b, double* r) {
    for (int i = 0; i < 3; ++i) r[i] = double(a[i]) - double(b[i]);
  };
  auto cross = [](const double* a, const double* b, double* r) {
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
  };
  auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  std::optional<Hit> best;
  double bestT = 1e30;
  for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    const Vertex* v[3] = {&mesh.vertices[mesh.indices[k]], &mesh.vertices[mesh.indices[k + 1]],
                          &mesh.vertices[mesh.indices[k + 2]]};
    double e1[3], e2[3], p[3], s[3], q[3];
    sub(v[1]->position, v[0]->position, e1);
    sub(v[2]->position, v[0]->position, e2);
    cross(dir, e2, p);
    const double det = dot(e1, p);
    if (std::fabs(det) < 1e-12) continue;
    for (int i = 0; i < 3; ++i) s[i] = eye[i] - v[0]->position[i];
    const double u = dot(s, p) / det;
    cross(s, e1, q);
    const double w = dot(dir, q) / det, t = dot(e2, q) / det;
    if (u < 0.0 || w < 0.0 || u + w > 1.0 || t <= 0.0 || t >= bestT) continue;
    bestT = t;
    Hit h;
    for (int i = 0; i < 3; ++i) {
      h.position[i] = eye[i] + t * dir[i];
      h.normal[i] = (1.0 - u - w) * v[0]->normal[i] + u * v[1]->normal[i] + w * v[2]->normal[i];
    }
    best = h;
  }
  return best;
}

}  // namespace engine
