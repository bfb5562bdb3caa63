"""sph_load: a load generator for sph_server (see clients/python/README.md)."""
