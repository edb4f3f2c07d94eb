package dev.strahl.accel;

/**
 * Per-thread working memory of a BVH traversal: the nodes still to visit and the distance at
 * which the ray enters each, so that a node farther than the closest hit found meanwhile is
 * skipped without touching its box again. Never share one between threads.
 */
public final class TraversalStack {
    final int[] nodes = new int[Bvh.STACK_SIZE];
    final double[] entry = new double[Bvh.STACK_SIZE];
}
