"""Seal cross-section meshes: structured quads for verification, gmsh for seal geometries."""
