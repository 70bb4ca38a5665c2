// Compare A/B in the window: side A is the table being edited and the pipeline's settings, side B
// another table or parameter file (or both); the comparison (visioncore/services/ab_compare.h)
// runs over the annotated frames (as the annotations document holds them) in the background with
// progress and cancel, and lists per class the frames B fixed and broke. Choosing a frame shows
// it.
#pragma once

#include "ui/document/editing_session.h"
#include "visioncore/services/ab_compare.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;
class QTreeWidget;
class QTreeWidgetItem;

namespace fieldsight::ui {

class AbCompareDialog : public QDialog
{
    Q_OBJECT
public:
    explicit AbCompareDialog(EditingSession& session, QWidget* parent = nullptr);
    /// Cancels a comparison that runs and waits for it (it stops after the frame it is on).
    ~AbCompareDialog() override;

    /// Side B's table (empty: A's) and parameters (empty: A's); an Error, with nothing changed,
    /// when the file cannot be read or does not fit the pipeline.
    Status setTableB(const QString& path);
    Status setParamsB(const QString& path);
    /// Starts with a copy of the annotations document; false, with the reason shown, when it
    /// cannot.
    bool start();
    void cancel();
    bool running() const { return m_watcher.isRunning(); }
    /// The last comparison that finished (none while one runs, or after a cancel).
    const std::optional<AbComparison>& result() const { return m_result; }
    /// The line under the buttons: what runs, what came out, or why not.
    QString status() const;
    QTreeWidget& frameList() { return *m_tree; }

signals:
    /// A comparison ended: finished, cancelled or failed.
    void comparisonEnded();

private:
    struct Outcome
    {
        Result<AbComparison> comparison = AbComparison{};
        double seconds = 0;
    };
    void chooseTable();
    void chooseParams();
    void refreshSides();
    void onFinished();
    void fill(const AbComparison& c);

    EditingSession& m_session;
    QString m_table_path;
    std::shared_ptr<const ColourLut> m_table;
    QString m_params_path;
    std::optional<ParamSet> m_params;

    QLabel* m_sides = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_cancel_button = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QTreeWidget* m_tree = nullptr;
    QTimer* m_poll = nullptr;

    std::atomic<bool> m_cancel{false};
    std::atomic<std::size_t> m_done{0};
    std::atomic<std::size_t> m_total{0};
    QFutureWatcher<Outcome> m_watcher;
    std::optional<AbComparison> m_result;
};

} // namespace fieldsight::ui
