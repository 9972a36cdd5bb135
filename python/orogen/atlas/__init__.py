"""The results atlas: a static web site of every run, sweep and ensemble under a folder
(`orogen report DIR --out SITE`, docs/atlas.md)."""
