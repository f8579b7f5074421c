"""sealts: transient soft-EHL simulation of reciprocating rod seals on PETSc."""
