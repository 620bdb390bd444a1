#pragma once
// The fish's NURBS skin (fish/skin.hpp) as render/ draws it: shared by the fish kind's own artifacts
// and its render hook (Kind::renderHook(), kinds/fish_render.cpp).
#include "fish/skin.hpp"
#include "render/mesh_export.hpp"
#include "render/triangle_mesh.hpp"

namespace creaturelab::kinds {

// The skin's mesh for render/: our z up becomes render's y up, (x, y, z) -> (x, z, -y), a rotation of
// -90 degrees about x, so triangles keep their orientation. Part per vertex: 0 the body's two halves,
// 1 the fins (dorsal, ventral, pectoral).
render::TriangleMesh fishRenderMesh(const fish::SkinMesh& skin);

// How the skin looks in its .glb.
render::GltfLook fishSkinLook();

}  // namespace creaturelab::kinds
