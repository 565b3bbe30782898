// contactfx internal: a uniform grid of boxes, for finding the shapes near a particle in O(1).
//
// Box2D's dynamic tree answers "what overlaps this box" in O(log n) with pointer chasing and a virtual
// callback per hit; a particle system asks that question for every particle every step, and its
// answers rarely change. A uniform grid over the shapes' bounds, stored as compressed rows (the items of
// cell c are items[cellStart[c] .. cellStart[c + 1])), answers it with two float-to-int conversions and a
// contiguous read. Boxes outside the grid's bounds overlap nothing, so a particle far from all geometry
// costs one box test.
//
// A grid lists each item either in the cells its box overlaps, or in every cell within one cell of
// those (its neighbourhood). The second takes about three times the memory and answers "what is near
// this point" from a single cell: the cell's list holds every item within a cell's width of any point in
// it, with no item met twice and nothing to merge.
//
// A grid stores its cells' lists in one of two ways. Dense: an array over every cell of the bounds, one
// load per cell visited; its cells must grow when the bounds are large for the items, so geometry spread
// thinly over kilometres (a level with one fixture far away) gets cells listing many items each. Hashed:
// only the cells that list something, in an open-addressed table, a hash and a probe or two per cell
// visited; its cell size follows the items whatever their bounds. Storage::automatic (the static geometry)
// is dense unless its cells would come out more than 8 times too large, then hashed; the moving bodies,
// rebuilt every step, are dense.
//
// Build allocates only when the grid needs more room than any earlier build; Query and Around are const
// and safe from any number of threads at once.
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
    /// Where a grid lists an item.
    enum class Listing : std::uint8_t
    {
        overlapped,   ///< in the cells its box overlaps
        neighbourhood ///< also in the cells next to those (their 3 x 3 blocks)
    };

    /// How the cells' lists are stored (see the top of this file).
    enum class Storage : std::uint8_t
    {
        dense,    ///< every cell of the bounds
        hashed,   ///< only the cells that list something
        automatic ///< dense, unless its cells would be more than 8 times as large as the boxes call for
    };

    /// Whether item `item` (whose box overlaps `region`) comes into `region` itself: lets a grid of
    /// large shapes that fill little of their boxes (a long rotated ramp) list each only in the cells it
    /// really comes near. Must be true whenever the item overlaps `region` (false only when it cannot).
    using Touches = bool (*)(const void* context, std::uint32_t item, const b2AABB& region);

    /// Lists every box as `listing` says. The cell size follows the boxes' median extent, grown until
    /// there are at most max(1024, 16 * boxes) cells (hashed: entries, counted as the cells the boxes
    /// overlap, at most 9 times that for a neighbourhood listing, and at most 2^24 columns and rows) and,
    /// when `maxItemsPerBox` > 0, at most that many list entries per box on average (times the 3 x 3 block
    /// for a neighbourhood listing). With `maxItemsPerBox` > 0 a build allocates only when it has more
    /// boxes than any earlier one, however the boxes are spread (for the moving bodies, which spread out
    /// and fall out of the world).
    ///
    /// With `touches`, a cell lists an item only when the item comes into the region the cell's list
    /// covers (the cell, or its 3 x 3 block for a neighbourhood listing), and the cells are no larger than
    /// 1,024 of them over the bounds would be: few large shapes then get cells about as fine as many
    /// small ones, each cell listing only what is near it. A build with `touches` also keeps room for as
    /// many boxes of the same extents placed anywhere on the cells (see ReserveForAnyAlignment).
    void Build(std::span<const b2AABB> boxes, Listing listing = Listing::overlapped,
               std::size_t maxItemsPerBox = 0, Touches touches = nullptr, const void* context = nullptr,
               Storage storage = Storage::dense);

    /// Calls visit(item) for every item whose box overlaps `box`, and some others; an item may be
    /// visited more than once. Returns a box that contains `box`, its sides on the grid's edges pushed to
    /// infinity: no item that was not visited overlaps it, so a point inside is at least its distance to
    /// the returned box's sides away from every such item. A neighbourhood grid visits every third cell
    /// in each direction (each cell's list covers its neighbours).
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
        // The cells visited, every (2 spread + 1)-th; each lists what lies `spread` cells on either side.
        const int spread = Spread();
        const int stride = 2 * spread + 1;
        if (m_storage == Storage::hashed &&
            static_cast<double>((x1 - x0) / stride + 1) * static_cast<double>((y1 - y0) / stride + 1) >
                static_cast<double>(m_hashed.size()))
        {
            // More cells to visit than the table has slots (a very fast particle among fine cells): every
            // cell listing something in the range instead, each listing what lies `spread` cells beyond.
            VisitHashedRange(x0, x1, y0, y1, visit);
            return CellsBox(x0 - spread, x1 + spread, y0 - spread, y1 + spread);
        }
        const int firstX = std::min(x0 + spread, x1);
        const int firstY = std::min(y0 + spread, y1);
        int lastX = firstX;
        int lastY = firstY;
        for (int y = firstY;; y = std::min(y + stride, y1))
        {
            for (int x = firstX;; x = std::min(x + stride, x1))
            {
                for (const std::uint32_t item : Cell(x, y))
                {
                    visit(item);
                }
                if (x + spread >= x1)
                {
                    lastX = x;
                    break;
                }
            }
            if (y + spread >= y1)
            {
                lastY = y;
                break;
            }
        }
        return CellsBox(firstX - spread, lastX + spread, firstY - spread, lastY + spread);
    }

    /// The items of the cell holding `point` (of the nearest cell when `point` is outside the grid's
    /// bounds). In a neighbourhood grid an item not among them is more than CellSize() from `point`.
    std::span<const std::uint32_t> Around(b2Vec2 point) const
    {
        if (m_items.empty())
        {
            return {};
        }
        return Cell(Column(point.x), Row(point.y));
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
    static constexpr std::uint64_t kNoCell = ~std::uint64_t{0}; ///< an empty slot's key

    // The items of the cell in column x, row y (both inside the grid).
    std::span<const std::uint32_t> Cell(int x, int y) const
    {
        if (m_storage == Storage::dense)
        {
            const std::size_t at = DenseIndex(x, y);
            return {m_items.data() + m_cellStart[at], m_items.data() + m_cellStart[at + 1]};
        }
        const HashedCell& cell = m_hashed[Slot(Key(x, y))];
        return {m_items.data() + cell.begin, m_items.data() + cell.end};
    }
    // Dense: the cell's index in m_cellStart.
    std::size_t DenseIndex(int x, int y) const
    {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_columns) +
               static_cast<std::size_t>(x);
    }
    // Hashed: the cell's key in the table.
    std::uint64_t Key(int x, int y) const
    {
        return static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(m_columns) +
               static_cast<std::uint64_t>(x);
    }
    // The slot holding `key`, or the empty slot where its probe ends (whose list is empty). Linear
    // probing from a multiplicative hash, scaled to the table's size without a division.
    std::size_t Slot(std::uint64_t key) const
    {
        const std::uint64_t hash = (key * 0x9E3779B97F4A7C15ull) >> 32;
        std::size_t slot = static_cast<std::size_t>((hash * m_hashed.size()) >> 32);
        while (m_hashed[slot].key != key && m_hashed[slot].key != kNoCell)
        {
            slot = slot + 1 == m_hashed.size() ? 0 : slot + 1;
        }
        return slot;
    }
    // Hashed: visits the items of every cell listing something in columns [x0, x1] and rows [y0, y1].
    template <typename Visit> void VisitHashedRange(int x0, int x1, int y0, int y1, Visit& visit) const
    {
        const auto columns = static_cast<std::uint64_t>(m_columns);
        for (const HashedCell& cell : m_hashed)
        {
            if (cell.key == kNoCell)
            {
                continue;
            }
            const auto x = static_cast<int>(cell.key % columns);
            const auto y = static_cast<int>(cell.key / columns);
            if (x < x0 || x > x1 || y < y0 || y > y1)
            {
                continue;
            }
            for (std::uint32_t k = cell.begin; k < cell.end; ++k)
            {
                visit(m_items[k]);
            }
        }
    }
    // Finds the cell size for the grid's storage from `cell` up (see Build); sets the columns, rows and cell
    // size.
    void Fit(std::span<const b2AABB> boxes, float cell, std::size_t maxCells, std::size_t maxItems);
    // How many cells on every side of the cells an item overlaps also list it.
    int Spread() const { return m_listing == Listing::neighbourhood ? 1 : 0; }
    // The box of columns [x0, x1] and rows [y0, y1], its sides on or beyond the grid's edges at infinity.
    b2AABB CellsBox(int x0, int x1, int y0, int y1) const
    {
        constexpr float kEdge = std::numeric_limits<float>::infinity();
        b2AABB box;
        box.lowerBound.x = x0 <= 0 ? -kEdge : Edge(m_lower.x, x0);
        box.lowerBound.y = y0 <= 0 ? -kEdge : Edge(m_lower.y, y0);
        box.upperBound.x = x1 >= m_columns - 1 ? kEdge : Edge(m_lower.x, x1 + 1);
        box.upperBound.y = y1 >= m_rows - 1 ? kEdge : Edge(m_lower.y, y1 + 1);
        return box;
    }
    // Where the cell line `line` lies, from the grid's lower side `lower`. Hashed grids compute it, and
    // cells (Column, Row), in doubles: their fine cells may lie kilometres from the lower side (one fixture
    // far away), where floats would place a line off by a good part of a cell, and a cell would not list a
    // primitive that its index says lies in it (a fuzz found sweeps missing touches so).
    float Edge(float lower, int line) const
    {
        return m_storage == Storage::hashed
                   ? static_cast<float>(static_cast<double>(lower) +
                                        static_cast<double>(line) * static_cast<double>(m_cellSize))
                   : lower + static_cast<float>(line) * m_cellSize;
    }
    // Clamped before the conversion, so that far, huge or not-a-number coordinates convert no value an
    // int cannot hold (NaN goes to 0). Two selects the compiler makes a max and a min, without a branch:
    // every particle asks, and which side of a cell it is on is as good as random.
    int Column(float x) const { return Line(x, m_lower.x, m_columns - 1); }
    int Row(float y) const { return Line(y, m_lower.y, m_rows - 1); }
    int Line(float at, float lower, int last) const
    {
        return m_storage == Storage::hashed
                   ? Clamped((static_cast<double>(at) - static_cast<double>(lower)) * m_inverseCellWide, last)
                   : Clamped((at - lower) * m_inverseCell, last);
    }
    // `last` converts exactly: Build makes at most 2^24 cells (hashed: columns, and rows).
    template <typename Real> static int Clamped(Real cell, int last)
    {
        const Real low = cell > Real{0} ? cell : Real{0};
        const auto high = static_cast<Real>(last);
        return static_cast<int>(low < high ? low : high);
    }
    /// With `touches` (the static geometry), or hashed: room for a build of these boxes in the current cells
    /// wherever they sit relative to them, so that rebuilding as many primitives after the origin shifted
    /// (they line up with the cells differently) allocates nothing. Returns the most entries such a build can
    /// list.
    std::size_t ReserveForAnyAlignment(std::span<const b2AABB> boxes);
    // Entries a build with the current cells would list.
    std::size_t CountItems(std::span<const b2AABB> boxes) const;

    b2Vec2 m_lower{0.0f, 0.0f};
    b2Vec2 m_upper{0.0f, 0.0f};
    float m_cellSize = 1.0f;
    float m_inverseCell = 1.0f;
    double m_inverseCellWide = 1.0; ///< hashed: 1 / m_cellSize in doubles
    int m_columns = 0;
    int m_rows = 0;
    Listing m_listing = Listing::overlapped;
    Storage m_storage = Storage::dense;
    /// Dense: by cell, columns * rows + 1 (1 when empty): the items of cell c are
    /// m_items[m_cellStart[c] .. m_cellStart[c + 1]).
    std::vector<std::uint32_t> m_cellStart;
    /// A hashed grid's cell: its key (Key; kNoCell: an empty slot) and its items, m_items[begin .. end).
    struct HashedCell
    {
        std::uint64_t key;
        std::uint32_t begin, end;
    };
    /// Hashed: twice as many slots as cells listing something. Their items lie in m_items in the cells'
    /// row-major order, so a row's neighbouring cells list from neighbouring memory.
    std::vector<HashedCell> m_hashed;
    /// Hashed, while building: (cell key, item) for every entry, sorted into m_items.
    struct Entry
    {
        std::uint64_t key;
        std::uint32_t item;
    };
    std::vector<Entry> m_entries;
    std::vector<std::uint32_t> m_items;
    std::vector<float> m_scratch;
    std::size_t m_reservedBoxes = 0; ///< the most boxes a build with an item budget has reserved room for
};

} // namespace cfx::particles
