// contactfx internal: the uniform grid (see grid.h). Built by a counting sort: count per cell, prefix
// sum, fill, so the items of a cell keep the boxes' order and the build is deterministic.
#include "particles/grid.h"

#include <algorithm>
#include <cmath>

namespace cfx::particles
{

namespace
{

constexpr float kMinCell = 1.0f / 64.0f; // m
constexpr std::size_t kMinCells = 1024;
constexpr std::size_t kMaxCells = std::size_t{1} << 24;
constexpr std::size_t kCellsPerBox = 16;
constexpr float kCellPerExtent = 1.0f;
// Storage::automatic hashes when dense cells would be more than this many times the size the boxes call for.
// A hashed cell costs a hash and a probe or two where a dense one costs a load, and a query of a fast
// particle visits dozens: 5,000 particles raining on a chain of 5 cm segments (contactfx_bench's FarFixture,
// one box far away) took 0.18 ms a step dense and 0.26 ms hashed with dense cells 5 times too large (the box
// 1 km away on the chain's line), 0.39 and 0.26 ms at 16 times (10 km), 1.25 and 0.30 ms at 110 times (1 km
// away diagonally).
constexpr float kHashedAbove = 8.0f;

// The part of `region` inside `box` (which it overlaps): an item inside its box comes into `region`
// exactly when it comes into that part, and that part is finite where the region's sides at the grid's
// edges are not.
b2AABB Within(const b2AABB& region, const b2AABB& box)
{
    b2AABB part;
    part.lowerBound = b2Max(region.lowerBound, box.lowerBound);
    part.upperBound = b2Min(region.upperBound, box.upperBound);
    return part;
}

} // namespace

void Grid::Build(std::span<const b2AABB> boxes, Listing listing, std::size_t maxItemsPerBox, Touches touches,
                 const void* context, Storage storage)
{
    m_listing = listing;
    m_items.clear();
    m_columns = 0;
    m_rows = 0;
    m_storage = Storage::dense;
    if (boxes.empty())
    {
        m_cellStart.assign(1, 0);
        return;
    }
    b2AABB bounds = boxes[0];
    m_scratch.clear();
    for (const b2AABB& box : boxes)
    {
        bounds.Combine(box);
        const b2Vec2 extent = box.upperBound - box.lowerBound;
        m_scratch.push_back(std::max(extent.x, extent.y));
    }
    auto middle = m_scratch.begin() + static_cast<std::ptrdiff_t>(m_scratch.size() / 2);
    std::nth_element(m_scratch.begin(), middle, m_scratch.end());
    float cell = kCellPerExtent * *middle;
    const b2Vec2 size = bounds.upperBound - bounds.lowerBound;
    if (touches != nullptr)
    {
        cell = std::min(cell, std::sqrt(size.x * size.y / static_cast<float>(kMinCells)));
    }
    cell = std::max(cell, kMinCell);
    const std::size_t maxCells = std::min(std::max(kMinCells, kCellsPerBox * boxes.size()), kMaxCells);
    m_lower = bounds.lowerBound;
    m_upper = bounds.upperBound;
    const int spread = Spread();
    const std::size_t listed = static_cast<std::size_t>((2 * spread + 1) * (2 * spread + 1));
    const std::size_t maxItems = maxItemsPerBox * listed * boxes.size();
    if (boxes.size() > m_reservedBoxes && maxItemsPerBox > 0)
    {
        // Everything a build of this many boxes can need: later builds of as many boxes, wherever they
        // are, allocate nothing.
        m_cellStart.reserve(maxCells + 1);
        m_items.reserve(maxItems);
        m_reservedBoxes = boxes.size();
    }
    m_storage = storage == Storage::hashed ? Storage::hashed : Storage::dense;
    Fit(boxes, cell, maxCells, maxItems);
    if (storage == Storage::automatic && m_cellSize > kHashedAbove * cell)
    {
        // Bounds large for the items (a fixture far away): dense cells would each list many.
        m_storage = Storage::hashed;
        Fit(boxes, cell, maxCells, maxItems);
    }

    // The cells listing a box: those it overlaps, and `spread` more on every side; with `touches`, only
    // those whose covered region the item comes into.
    auto forCells = [&](std::uint32_t index, auto&& use)
    {
        const b2AABB& box = boxes[index];
        const int x0 = std::max(Column(box.lowerBound.x) - spread, 0);
        const int x1 = std::min(Column(box.upperBound.x) + spread, m_columns - 1);
        const int y0 = std::max(Row(box.lowerBound.y) - spread, 0);
        const int y1 = std::min(Row(box.upperBound.y) + spread, m_rows - 1);
        for (int y = y0; y <= y1; ++y)
        {
            for (int x = x0; x <= x1; ++x)
            {
                if (touches == nullptr ||
                    touches(context, index,
                            Within(CellsBox(x - spread, x + spread, y - spread, y + spread), box)))
                {
                    use(x, y);
                }
            }
        }
    };
    if (m_storage == Storage::hashed)
    {
        // Every entry as (cell, item), sorted by cell and then item: the items of a cell keep the boxes'
        // order, and the cells lie in row-major order.
        const std::size_t room = ReserveForAnyAlignment(boxes);
        m_entries.reserve(room);
        m_entries.clear();
        for (std::uint32_t index = 0; index < boxes.size(); ++index)
        {
            forCells(index, [&](int x, int y) { m_entries.push_back(Entry{Key(x, y), index}); });
        }
        std::sort(m_entries.begin(), m_entries.end(),
                  [](const Entry& a, const Entry& b)
                  { return a.key != b.key ? a.key < b.key : a.item < b.item; });
        std::size_t cells = 0;
        m_items.resize(m_entries.size());
        for (std::size_t k = 0; k < m_entries.size(); ++k)
        {
            m_items[k] = m_entries[k].item;
            cells += k == 0 || m_entries[k].key != m_entries[k - 1].key ? 1 : 0;
        }
        // Twice the slots of the cells listing something (probes stay short), with room for as many as
        // any alignment of these boxes can list.
        m_hashed.reserve(2 * room + 2);
        m_hashed.assign(2 * cells + 2, HashedCell{kNoCell, 0, 0});
        for (std::size_t begin = 0; begin < m_entries.size();)
        {
            std::size_t end = begin + 1;
            while (end < m_entries.size() && m_entries[end].key == m_entries[begin].key)
            {
                ++end;
            }
            m_hashed[Slot(m_entries[begin].key)] = HashedCell{
                m_entries[begin].key, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
            begin = end;
        }
        return;
    }
    if (touches != nullptr)
    {
        ReserveForAnyAlignment(boxes);
    }
    const std::size_t cells = static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(m_rows);
    m_cellStart.assign(cells + 1, 0);
    for (std::uint32_t index = 0; index < boxes.size(); ++index)
    {
        forCells(index, [&](int x, int y) { ++m_cellStart[DenseIndex(x, y) + 1]; });
    }
    for (std::size_t c = 0; c < cells; ++c)
    {
        m_cellStart[c + 1] += m_cellStart[c];
    }
    m_items.resize(m_cellStart[cells]);
    // Fill using the row starts as cursors, then shift them back.
    for (std::uint32_t index = 0; index < boxes.size(); ++index)
    {
        forCells(index, [&](int x, int y) { m_items[m_cellStart[DenseIndex(x, y)]++] = index; });
    }
    for (std::size_t c = cells; c > 0; --c)
    {
        m_cellStart[c] = m_cellStart[c - 1];
    }
    m_cellStart[0] = 0;
}

void Grid::Fit(std::span<const b2AABB> boxes, float cell, std::size_t maxCells, std::size_t maxItems)
{
    const b2Vec2 size = m_upper - m_lower;
    const std::size_t listed = static_cast<std::size_t>((2 * Spread() + 1) * (2 * Spread() + 1));
    for (;;)
    {
        const double columns = std::floor(static_cast<double>(size.x) / cell) + 1.0;
        const double rows = std::floor(static_cast<double>(size.y) / cell) + 1.0;
        // At most 2^24 cells (hashed: columns, and rows), so that every column and row index is exact as
        // a float (Clamped).
        const bool fits = m_storage == Storage::dense
                              ? columns * rows <= static_cast<double>(maxCells)
                              : std::max(columns, rows) <= static_cast<double>(kMaxCells);
        if (fits)
        {
            m_columns = static_cast<int>(columns);
            m_rows = static_cast<int>(rows);
            m_cellSize = cell;
            m_inverseCell = 1.0f / cell;
            m_inverseCellWide = 1.0 / static_cast<double>(cell);
            const std::size_t items = maxItems > 0 || m_storage == Storage::hashed ? CountItems(boxes) : 0;
            if ((maxItems == 0 || items <= maxItems) &&
                (m_storage == Storage::dense || items <= listed * maxCells))
            {
                return;
            }
        }
        cell *= 1.5f;
    }
}

std::size_t Grid::ReserveForAnyAlignment(std::span<const b2AABB> boxes)
{
    // A box w wide covers at most floor(w / cell) + 2 columns however it sits on the cells, and the grid
    // one more column than now; the same for rows. The 0.1 % covers a cell size that rounding changes.
    const int spread = Spread();
    const float perCell = 1.001f * m_inverseCell;
    const auto most = [&](float extent, int lines)
    {
        const double covered = std::floor(static_cast<double>(extent * perCell)) + 2.0 + 2.0 * spread;
        return static_cast<std::size_t>(std::min(covered, static_cast<double>(lines) + 1.0));
    };
    std::size_t items = 0;
    for (const b2AABB& box : boxes)
    {
        const b2Vec2 extent = box.upperBound - box.lowerBound;
        items += most(extent.x, m_columns) * most(extent.y, m_rows);
    }
    m_items.reserve(items);
    if (m_storage == Storage::dense)
    {
        m_cellStart.reserve(
            (static_cast<std::size_t>(m_columns) + 1) * (static_cast<std::size_t>(m_rows) + 1) + 1);
    }
    return items;
}

std::size_t Grid::CountItems(std::span<const b2AABB> boxes) const
{
    const int spread = Spread();
    std::size_t items = 0;
    for (const b2AABB& box : boxes)
    {
        const int x0 = std::max(Column(box.lowerBound.x) - spread, 0);
        const int x1 = std::min(Column(box.upperBound.x) + spread, m_columns - 1);
        const int y0 = std::max(Row(box.lowerBound.y) - spread, 0);
        const int y1 = std::min(Row(box.upperBound.y) + spread, m_rows - 1);
        items += static_cast<std::size_t>(x1 - x0 + 1) * static_cast<std::size_t>(y1 - y0 + 1);
    }
    return items;
}

std::size_t Grid::Bytes() const
{
    return (m_cellStart.capacity() + m_items.capacity()) * sizeof(std::uint32_t) +
           m_hashed.capacity() * sizeof(HashedCell) + m_entries.capacity() * sizeof(Entry) +
           m_scratch.capacity() * sizeof(float);
}

} // namespace cfx::particles
