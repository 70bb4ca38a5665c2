// Compare the edited LUT with another table (any importable format): the cells that differ, by
// class pair, as a table; choosing a row shows those cells in the UV plane and their pixels in
// the image. Merge chosen classes of the other table into the edited one, with a preview of how
// many cells change and how many are taken from another class, as one undoable edit.
#pragma once

#include "ui/document/lut_document.h"
#include "visioncore/services/lut_compare.h"

#include <QDialog>

#include <map>

class QCheckBox;
class QLabel;
class QTableWidget;

namespace fieldsight::ui {

class LutCompareDialog : public QDialog
{
    Q_OBJECT
public:
    /// Compares `doc`'s table with `other` (read from `other_path`).
    LutCompareDialog(LutDocument& doc, ColourLut other, const QString& other_path,
                     QWidget* parent = nullptr);

    /// Rows of the table: (class here, class in the other table) -> cells.
    const std::map<std::pair<Colour, Colour>, std::size_t>& pairs() const { return m_pairs; }
    /// The classes to merge (all of the other table's classes at first).
    void setMergeClasses(const std::vector<Colour>& classes);
    void setMergeKeepsOthers(bool keep);
    /// What a merge would change now.
    std::vector<CellChange> plannedMerge() const;
    QString mergePreview() const;
    /// Merges as one undoable edit; false when nothing changes.
    bool merge();

signals:
    /// The cells of the chosen row (empty: none), to show in the UV plane and the image.
    void cellsChosen(const std::vector<std::uint32_t>& cells);

private:
    void refresh();
    void refreshPreview();

    LutDocument& m_doc;
    ColourLut m_other;
    QString m_other_name;
    LutDiff m_diff;
    std::map<std::pair<Colour, Colour>, std::size_t> m_pairs;
    QTableWidget* m_table = nullptr;
    std::map<Colour, QCheckBox*> m_merge_boxes;
    QCheckBox* m_keep_others = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_preview = nullptr;
};

} // namespace fieldsight::ui
