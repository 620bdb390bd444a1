# tests for physics/render: every frame of a real swim (the jellyfish kind on the paper's 100² grid)
# renders to a closed, manifold, outward mesh (Rudolf & Mould 2009 §3.5). A few seconds in Release.
creaturelab_test(render_physics_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_swim_test.cpp
  LIBS cl_kinds cl_render
)
