"""One module per node, named like its script in ``scripts/``: each reads its
parameters, wires topics to the library's objects and spins."""
