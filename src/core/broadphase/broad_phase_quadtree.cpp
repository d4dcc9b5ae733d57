#include "broadphase/broad_phase_quadtree.hpp"

#include <algorithm>
#include <cmath>

#include "broadphase/disc_overlap.hpp"
#include "support/parallel.hpp"

namespace psb {
namespace {

/// Spreads the low 16 bits of v to the even bits of the result.
inline std::uint32_t spreadBits(std::uint32_t v) {
    v &= 0xffffu;
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

inline std::uint32_t quantize(double v, double origin, double scale) {
    const double f = (v - origin) * scale;
    if (!(f > 0.0)) return 0;
    if (f >= 65535.0) return 65535;
    return static_cast<std::uint32_t>(f);
}

}  // namespace

void QuadtreeBroadPhase::build(const ParticleArrays& p, const ParticleStats& s, int threads) {
    const std::size_t n = p.size();
    code_.resize(n);
    order_.resize(n);
    codeTmp_.resize(n);
    orderTmp_.resize(n);
    slack_ = 64.0 * s.maxAbsCoordinate * 2.220446049250313e-16;
    const double side = std::max(s.maxX - s.minX, s.maxY - s.minY);
    const double scale = side > 0.0 ? 65536.0 / side : 0.0;
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    {
        std::uint32_t* code = code_.data();
        std::uint32_t* order = order_.data();
        parallel::forChunks(threads, parallel::chunksFor(threads, n), n,
                            [&](int, std::size_t begin, std::size_t end) {
                                for (std::size_t i = begin; i < end; ++i) {
                                    code[i] = spreadBits(quantize(x[i], s.minX, scale)) |
                                              (spreadBits(quantize(y[i], s.minY, scale)) << 1);
                                    order[i] = static_cast<std::uint32_t>(i);
                                }
                            });
    }
    // LSD radix sort by code, 8 bits per pass; stable, so equal codes stay in index order.
    for (int shift = 0; shift < 32; shift += 8) {
        std::uint32_t count[257] = {};
        for (std::size_t k = 0; k < n; ++k)
            ++count[((code_[k] >> shift) & 0xffu) + 1];
        for (int b = 0; b < 256; ++b)
            count[b + 1] += count[b];
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t dst = count[(code_[k] >> shift) & 0xffu]++;
            codeTmp_[dst] = code_[k];
            orderTmp_[dst] = order_[k];
        }
        code_.swap(codeTmp_);
        order_.swap(orderTmp_);
    }

    // Breadth-first split: nodes_ doubles as the work queue.
    nodes_.clear();
    level_.clear();
    leaves_.clear();
    nodes_.push_back({0, 0, 0, 0, 0, static_cast<std::uint32_t>(n), 0, 0});
    level_.push_back(0);
    depth_ = 0;
    const std::uint32_t* code = code_.data();
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const std::uint32_t begin = nodes_[k].begin, end = nodes_[k].end;
        const int level = level_[k];
        depth_ = std::max(depth_, level);
        if (end - begin <= kLeafSize || level >= kMaxDepth) {
            leaves_.push_back(static_cast<std::uint32_t>(k));
            continue;
        }
        const int shift = 2 * (kMaxDepth - 1 - level);
        auto quadrant = [&](std::uint32_t idx) { return (code[idx] >> shift) & 3u; };
        const auto firstChild = static_cast<std::uint32_t>(nodes_.size());
        std::uint32_t lo = begin;
        for (std::uint32_t q = 0; q < 4 && lo < end; ++q) {
            // First index in [lo, end) whose quadrant is above q (codes are sorted).
            std::uint32_t a = lo, b = end;
            while (a < b) {
                const std::uint32_t mid = a + (b - a) / 2;
                if (quadrant(mid) <= q) {
                    a = mid + 1;
                } else {
                    b = mid;
                }
            }
            if (a > lo) {
                nodes_.push_back({0, 0, 0, 0, lo, a, 0, 0});
                level_.push_back(static_cast<std::uint8_t>(level + 1));
                lo = a;
            }
        }
        nodes_[k].firstChild = firstChild;
        nodes_[k].childCount = static_cast<std::uint32_t>(nodes_.size()) - firstChild;
    }
    // Bounds of the discs, children before parents.
    for (std::size_t k = nodes_.size(); k-- > 0;) {
        Node& node = nodes_[k];
        double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
        if (node.childCount == 0) {
            for (std::uint32_t m = node.begin; m < node.end; ++m) {
                const std::uint32_t i = order_[m];
                minX = std::min(minX, x[i] - r[i]);
                maxX = std::max(maxX, x[i] + r[i]);
                minY = std::min(minY, y[i] - r[i]);
                maxY = std::max(maxY, y[i] + r[i]);
            }
        } else {
            for (std::uint32_t c = node.firstChild; c < node.firstChild + node.childCount; ++c) {
                minX = std::min(minX, nodes_[c].minX);
                maxX = std::max(maxX, nodes_[c].maxX);
                minY = std::min(minY, nodes_[c].minY);
                maxY = std::max(maxY, nodes_[c].maxY);
            }
        }
        node.minX = minX;
        node.minY = minY;
        node.maxX = maxX;
        node.maxY = maxY;
    }
}

void QuadtreeBroadPhase::findPairs(const ParticleArrays& p, int threads,
                                   std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    if (n < 2 || nodes_.empty()) return;
    const std::size_t leafCount = leaves_.size();
    const int chunks = parallel::chunksFor(threads, n);
    chunks_.prepare(chunks);
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    const Node* nodes = nodes_.data();
    const std::uint32_t* order = order_.data();
    const std::uint32_t* leaves = leaves_.data();
    parallel::forChunks(threads, chunks, leafCount, [&](int c, std::size_t begin, std::size_t end) {
        std::size_t found = 0;
        // Breadth is at most 4 per level below the current node, so a fixed stack suffices.
        std::uint32_t stack[4 * (kMaxDepth + 1) + 1];
        for (std::size_t li = begin; li < end; ++li) {
            const std::uint32_t self = leaves[li];
            const Node& leaf = nodes[self];
            // One traversal per leaf with the leaf's own bounds (plus rounding slack); the
            // exact test decides.
            const double qx0 = leaf.minX - slack_, qx1 = leaf.maxX + slack_;
            const double qy0 = leaf.minY - slack_, qy1 = leaf.maxY + slack_;
            int top = 0;
            stack[top++] = 0;
            while (top > 0) {
                const std::uint32_t k = stack[--top];
                const Node& node = nodes[k];
                if (node.minX > qx1 || node.maxX < qx0 || node.minY > qy1 || node.maxY < qy0) {
                    continue;
                }
                if (node.childCount != 0) {
                    for (std::uint32_t ch = 0; ch < node.childCount; ++ch) {
                        stack[top++] = node.firstChild + ch;
                    }
                    continue;
                }
                // Each pair of leaves once: from the lower-numbered one.
                if (k < self) continue;
                ContactPair* buf = chunks_.room(
                    c, found + std::size_t{leaf.end - leaf.begin} * (node.end - node.begin));
                for (std::uint32_t a = leaf.begin; a < leaf.end; ++a) {
                    const std::uint32_t i = order[a];
                    const double xi = x[i], yi = y[i], ri = r[i];
                    // Within one leaf, only the slots after a.
                    for (std::uint32_t b = k == self ? a + 1 : node.begin; b < node.end; ++b) {
                        const std::uint32_t j = order[b];
                        // discsOverlap's arithmetic, symmetric in i and j to the last bit.
                        const double dx = x[j] - xi;
                        const double dy = y[j] - yi;
                        const double rs = ri + r[j];
                        buf[found] = {std::min(i, j), std::max(i, j)};
                        found += static_cast<std::size_t>(dx * dx + dy * dy < rs * rs);
                    }
                }
            }
        }
        chunks_.setFound(c, found);
    });
    const std::size_t before = out.size();
    out.resize(before + chunks_.total());
    chunks_.copyTo(out.data() + before);
    sortPairs(out, before, sortScratch_, static_cast<std::uint32_t>(n));
}

void QuadtreeBroadPhase::findPairsPeriodic(const ParticleArrays& p, const periodic::Box& box,
                                           int threads, std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    if (n < 2 || nodes_.empty()) return;
    const std::size_t leafCount = leaves_.size();
    const int chunks = parallel::chunksFor(threads, n);
    chunks_.prepare(chunks);
    if (touched_.size() < static_cast<std::size_t>(chunks)) touched_.resize(chunks);
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    const Node* nodes = nodes_.data();
    const std::uint32_t* order = order_.data();
    const std::uint32_t* leaves = leaves_.data();
    const Node& root = nodes[0];
    parallel::forChunks(threads, chunks, leafCount, [&](int c, std::size_t begin, std::size_t end) {
        std::size_t found = 0;
        std::uint32_t stack[4 * (kMaxDepth + 1) + 1];
        std::vector<std::uint32_t>& touched = touched_[static_cast<std::size_t>(c)];
        for (std::size_t li = begin; li < end; ++li) {
            const std::uint32_t self = leaves[li];
            const Node& leaf = nodes[self];
            touched.clear();
            for (int sy = -1; sy <= 1; ++sy) {
                for (int sx = -1; sx <= 1; ++sx) {
                    const double ox = sx * box.width, oy = sy * box.height;
                    const double qx0 = leaf.minX + ox - slack_, qx1 = leaf.maxX + ox + slack_;
                    const double qy0 = leaf.minY + oy - slack_, qy1 = leaf.maxY + oy + slack_;
                    // An image that reaches nothing (the leaf is far from that edge).
                    if (root.minX > qx1 || root.maxX < qx0 || root.minY > qy1 || root.maxY < qy0) {
                        continue;
                    }
                    int top = 0;
                    stack[top++] = 0;
                    while (top > 0) {
                        const std::uint32_t k = stack[--top];
                        const Node& node = nodes[k];
                        if (node.minX > qx1 || node.maxX < qx0 || node.minY > qy1 ||
                            node.maxY < qy0) {
                            continue;
                        }
                        if (node.childCount != 0) {
                            for (std::uint32_t ch = 0; ch < node.childCount; ++ch)
                                stack[top++] = node.firstChild + ch;
                            continue;
                        }
                        if (k >= self) touched.push_back(k);
                    }
                }
            }
            std::sort(touched.begin(), touched.end());
            touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
            for (const std::uint32_t k : touched) {
                const Node& node = nodes[k];
                ContactPair* buf = chunks_.room(
                    c, found + std::size_t{leaf.end - leaf.begin} * (node.end - node.begin));
                for (std::uint32_t a = leaf.begin; a < leaf.end; ++a) {
                    const std::uint32_t i = order[a];
                    for (std::uint32_t b = k == self ? a + 1 : node.begin; b < node.end; ++b) {
                        const std::uint32_t j = order[b];
                        const std::uint32_t lo = std::min(i, j), hi = std::max(i, j);
                        buf[found] = {lo, hi};
                        found +=
                            static_cast<std::size_t>(discsOverlapPeriodic(x, y, r, lo, hi, box));
                    }
                }
            }
        }
        chunks_.setFound(c, found);
    });
    const std::size_t before = out.size();
    out.resize(before + chunks_.total());
    chunks_.copyTo(out.data() + before);
    sortPairs(out, before, sortScratch_, static_cast<std::uint32_t>(n));
}

std::size_t QuadtreeBroadPhase::memoryBytes() const {
    std::size_t bytes = sizeof(std::uint32_t) * (code_.capacity() + order_.capacity() +
                                                 codeTmp_.capacity() + orderTmp_.capacity());
    bytes += level_.capacity() + sizeof(Node) * nodes_.capacity();
    bytes += chunks_.memoryBytes();
    bytes +=
        sizeof(std::uint32_t) * leaves_.capacity() + sizeof(ContactPair) * sortScratch_.capacity();
    return bytes;
}

}  // namespace psb
