"""vibrofriction: friction under normal oscillations (Mao, Popov, Starcevic, Popov 2017)."""
__version__ = "0.1.0"
