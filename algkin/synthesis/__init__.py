"""Synthesis: from a wanted motion to the mechanisms that give it, every solution certified.

Motion generation (Burmester: poses of a moving plane), function generation (Freudenstein:
pairs of crank and rocker angles) and path generation (a coupler point through given points)
are each a polynomial system over QQ, solved completely by elimination; each real solution is
a four-bar, written as a scene and checked by algkin's own derivation.
"""
