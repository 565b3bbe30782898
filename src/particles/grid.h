// contactfx internal: a uniform grid of boxes, for finding the shapes near a particle in O(1).
//
// Box2D's dynamic tree answers "what overlaps this box" in O(log n) with pointer chasing and a virtual
// callback per hit; a particle system asks that question for every particle every step, and its
// answers rarely change. A uniform grid over the shapes' bounds, stored as compressed rows (the items of
// cell c are items[cellStart[c] .. cellStart[c + 1])), answers it with two float-to-int conversions and a
// contiguous read. An item is listed in every cell its box overlaps. Boxes outside the grid's bounds
// overlap nothing, so a particle far from all geometry costs one box test.
//
// Build allocates only when the grid needs more room than any earlier build; Query is const and safe
// from any number of threads at once.
#pragma once

#include <algorithm>
#include <box2d/b2_collision.h>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace cfx::particles
{

class Grid
{
public:
    /// Lists every box in the cells it overlaps. The cell size follows the boxes' median extent,
    /// grown until there are at most max(1024, 16 * boxes) cells.
    void Build(std::span<const b2AABB> boxes);

    /// Calls visit(item) for the items listed in the cells `box` overlaps, cell by cell in row order;
    /// an item overlapping several of those cells is visited once per cell. Returns the box those
    /// cells cover, its sides on the grid's edges pushed to infinity: no item that was not visited
    /// overlaps it, so a point inside is at least its distance to the returned box's sides away from
    /// every such item. It contains `box`.
    template <typename Visit> b2AABB Query(const b2AABB& box, Visit&& visit) const
    {
        if (m_items.empty() || box.upperBound.x < m_lower.x || box.upperBound.y < m_lower.y ||
            box.lowerBound.x > m_upper.x || box.lowerBound.y > m_upper.y)
        {
            return box;
        }
        const int x0 = Column(box.lowerBound.x);
        const int x1 = Column(box.upperBound.x);
        const int y0 = Row(box.lowerBound.y);
        const int y1 = Row(box.upperBound.y);
        for (int y = y0; y <= y1; ++y)
        {
            const std::uint32_t* start = m_cellStart.data() + y * m_columns;
            for (int x = x0; x <= x1; ++x)
            {
                for (std::uint32_t k = start[x]; k < start[x + 1]; ++k)
                {
                    visit(m_items[k]);
                }
            }
        }
        constexpr float kEdge = std::numeric_limits<float>::infinity();
        b2AABB covered;
        covered.lowerBound.x = x0 == 0 ? -kEdge : m_lower.x + static_cast<float>(x0) * m_cellSize;
        covered.lowerBound.y = y0 == 0 ? -kEdge : m_lower.y + static_cast<float>(y0) * m_cellSize;
        covered.upperBound.x =
            x1 == m_columns - 1 ? kEdge : m_lower.x + static_cast<float>(x1 + 1) * m_cellSize;
        covered.upperBound.y = y1 == m_rows - 1 ? kEdge : m_lower.y + static_cast<float>(y1 + 1) * m_cellSize;
        return covered;
    }

    /// The box every item lies in; an empty box (lower above upper, overlapping nothing) when there are
    /// no items.
    b2AABB Bounds() const
    {
        b2AABB bounds;
        bounds.lowerBound = m_items.empty() ? b2Vec2(b2_maxFloat, b2_maxFloat) : m_lower;
        bounds.upperBound = m_items.empty() ? b2Vec2(-b2_maxFloat, -b2_maxFloat) : m_upper;
        return bounds;
    }

    bool Empty() const { return m_items.empty(); }
    float CellSize() const { return m_cellSize; }
    int Columns() const { return m_columns; }
    int Rows() const { return m_rows; }
    /// Heap bytes held.
    std::size_t Bytes() const;

private:
    int Column(float x) const
    {
        const float cell = (x - m_lower.x) * m_inverseCell;
        return cell <= 0.0f ? 0 : std::min(static_cast<int>(cell), m_columns - 1);
    }
    int Row(float y) const
    {
        const float cell = (y - m_lower.y) * m_inverseCell;
        return cell <= 0.0f ? 0 : std::min(static_cast<int>(cell), m_rows - 1);
    }

    b2Vec2 m_lower{0.0f, 0.0f};
    b2Vec2 m_upper{0.0f, 0.0f};
    float m_cellSize = 1.0f;
    float m_inverseCell = 1.0f;
    int m_columns = 0;
    int m_rows = 0;
    std::vector<std::uint32_t> m_cellStart; ///< columns * rows + 1
    std::vector<std::uint32_t> m_items;
    std::vector<float> m_scratch;
};

} // namespace cfx::particles
