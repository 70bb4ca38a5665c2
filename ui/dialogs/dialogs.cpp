#include "ui/dialogs/dialogs.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QGuiApplication>
#include <QInputDialog>
#include <QPushButton>
#include <QScreen>
#include <QTextBrowser>
#include <QTextDocument>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>
#include <vector>

#include <utility>

namespace fieldsight::ui {

namespace {

/// Qt's modal dialogs.
class QtDialogs final : public Dialogs
{
public:
    QString openFile(QWidget* parent, const QString& title, const QString& dir,
                     const QString& filter) override
    {
        return QFileDialog::getOpenFileName(parent, title, dir, filter);
    }
    QString saveFile(QWidget* parent, const QString& title, const QString& suggestion,
                     const QString& filter) override
    {
        return QFileDialog::getSaveFileName(parent, title, suggestion, filter);
    }
    QString folder(QWidget* parent, const QString& title, const QString& dir) override
    {
        return QFileDialog::getExistingDirectory(parent, title, dir);
    }
    std::optional<QString> text(QWidget* parent, const QString& title, const QString& label,
                                const QString& initial) override
    {
        bool ok = false;
        const QString t =
            QInputDialog::getText(parent, title, label, QLineEdit::Normal, initial, &ok);
        return ok ? std::optional<QString>(t) : std::nullopt;
    }
    std::optional<int> number(QWidget* parent, const QString& title, const QString& label,
                              int initial, int min, int max) override
    {
        bool ok = false;
        const int n = QInputDialog::getInt(parent, title, label, initial, min, max, 1, &ok);
        return ok ? std::optional<int>(n) : std::nullopt;
    }
    QMessageBox::StandardButton question(QWidget* parent, const QString& title, const QString& text,
                                         QMessageBox::StandardButtons buttons,
                                         QMessageBox::StandardButton preferred) override
    {
        return QMessageBox::question(parent, title, text, buttons, preferred);
    }
    void information(QWidget* parent, const QString& title, const QString& text) override
    {
        QMessageBox::information(parent, title, text);
    }
    void document(QWidget* parent, const QString& title, const QString& html) override
    {
        std::unique_ptr<QDialog> dialog(makeDocumentDialog(parent, title, html));
        dialog->exec();
    }
    int choice(QWidget* parent, const QString& title, const QString& text,
               const QStringList& options, int preferred) override
    {
        QMessageBox box(QMessageBox::Question, title, text, QMessageBox::NoButton, parent);
        std::vector<QAbstractButton*> buttons;
        for (int i = 0; i < options.size(); ++i) {
            QPushButton* b = box.addButton(options[i], QMessageBox::AcceptRole);
            buttons.push_back(b);
            if (i == preferred)
                box.setDefaultButton(b);
        }
        box.addButton(QMessageBox::Cancel);
        box.exec();
        const auto it = std::find(buttons.begin(), buttons.end(), box.clickedButton());
        return it == buttons.end() ? -1 : int(it - buttons.begin());
    }
};

QtDialogs g_qt_dialogs;
Dialogs* g_installed = nullptr;

} // namespace

QDialog* makeDocumentDialog(QWidget* parent, const QString& title, const QString& html)
{
    auto* dialog = new QDialog(parent);
    dialog->setWindowTitle(title);
    auto* column = new QVBoxLayout(dialog);
    auto* view = new QTextBrowser(dialog);
    view->setObjectName(QStringLiteral("document.text"));
    view->setHtml(html);
    view->setFrameShape(QFrame::NoFrame);
    column->addWidget(view);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    column->addWidget(buttons);
    // As large as the text wants unwrapped, within 90% of the screen: the rest scrolls, Close
    // stays on it.
    QTextDocument unwrapped;
    unwrapped.setDefaultFont(view->font());
    unwrapped.setHtml(html);
    const QSize wanted = unwrapped.size().toSize() + QSize(40, 40);
    QSize room(1280, 800);
    if (const QScreen* screen = parent ? parent->screen() : QGuiApplication::primaryScreen())
        room = screen->availableSize();
    room = room * 0.9;
    const int buttons_height = buttons->sizeHint().height() + column->spacing() +
                               column->contentsMargins().top() + column->contentsMargins().bottom();
    dialog->resize(std::min(wanted.width(), room.width()),
                   std::min(wanted.height() + buttons_height, room.height()));
    return dialog;
}

Dialogs& Dialogs::current()
{
    return g_installed ? *g_installed : g_qt_dialogs;
}

Dialogs* Dialogs::install(Dialogs* dialogs)
{
    return std::exchange(g_installed, dialogs);
}

} // namespace fieldsight::ui
