"""Rigid analytical surfaces (rod, groove) and their contact laws with the seal."""
