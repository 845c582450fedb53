// The viewport's time-slicing arithmetic: moving divisors rise on overrun and fall when a finer one
// fits (never below half resolution); still views trace full-resolution bands sized to the budget
// from the measured cost of a row, with a preview divisor chosen so its frame fits; the mean's
// filter runs in steps from the cost of its rows; paints stop adding frames at the budget.
#include "editor/viewport/frame_budget.h"

#include <QtTest>

using glint::editor::FrameBudget;

class TestViewportBudget : public QObject {
    Q_OBJECT
private slots:
    void startsHalfMovingAndCautiousStill() {
        FrameBudget b(30.0);
        QCOMPARE(b.movingDivisor(), 2);
        // Nothing measured yet: a preview at 1/4 and bands of 1/16 of the image.
        QCOMPARE(b.previewDivisor(720), FrameBudget::kFirstPreviewDivisor);
        QCOMPARE(b.rowsPerFrame(720), 720 / FrameBudget::kFirstBands);
    }

    void movingOverrunCoarsensStepByStep() {
        FrameBudget b(30.0);
        b.reportMoving(40.0, 2);
        QCOMPARE(b.movingDivisor(), 3);
        b.reportMoving(500.0, 5); // a frame at a divisor no longer in use says nothing
        QCOMPARE(b.movingDivisor(), 3);
    }

    void movingFinerWhenItFits() {
        FrameBudget b(30.0);
        for (int i = 0; i < 3; ++i) b.reportMoving(100.0, b.movingDivisor());
        QCOMPARE(b.movingDivisor(), 5);
        b.reportMoving(5.0, 5); // 5 * 25 / 16 = 7.8 ms at 1/4: fits
        QCOMPARE(b.movingDivisor(), 4);
        b.reportMoving(1.0, 4);
        b.reportMoving(1.0, 3);
        QCOMPARE(b.movingDivisor(), 2); // never finer than half while moving
        for (int i = 0; i < 20; ++i) b.reportMoving(1000.0, b.movingDivisor());
        QCOMPARE(b.movingDivisor(), FrameBudget::kMaxDivisor);
    }

    // A fast GL: a whole full-resolution frame fits, so neither bands nor a preview.
    void wholeFramesWhereTheyFit() {
        FrameBudget b(30.0);
        b.reportRows(20.0, 720); // 20 ms for a whole 720-row frame
        QCOMPARE(b.rowsPerFrame(720), 720);
        QCOMPARE(b.previewDivisor(720), 1);
    }

    // A slow GL: 1 ms per row, a 720-row frame takes 720 ms: bands of 24 rows (80 % of 30 ms) and a
    // preview at ceil(sqrt(720 / 24)) = 6.
    void bandsAndPreviewOnASlowGl() {
        FrameBudget b(30.0);
        b.reportRows(10.0, 10);
        QCOMPARE(b.rowsPerFrame(720), 24);
        QCOMPARE(b.previewDivisor(720), 6);
        // The estimate follows new measures halfway: 3 ms per row now (a heavier part of the image).
        b.reportRows(30.0, 6);
        QCOMPARE(b.rowsPerFrame(720), 8);
        QCOMPARE(b.previewDivisor(720), FrameBudget::kMaxDivisor); // sqrt(2160 / 24) = 9.5, capped
    }

    // A preview frame at 1/4 with 180 rows in 45 ms: each full row costs 45 / 180 * 4 = 1 ms.
    void previewsTeachTheRowCost() {
        FrameBudget b(30.0);
        b.reportPreview(45.0, 180, 4);
        QCOMPARE(b.msPerRow(), 1.0);
        QCOMPARE(b.rowsPerFrame(720), 24);
    }

    // A whole frame fits (40 ms, 45 with the overrun) but not with the filtering of its mean (7
    // stages of 180 rows at 0.08 ms: 100 ms): the filtered preview stands in, at ceil(sqrt(140 / 24)).
    void previewWhereTheFilteringDoesNotFit() {
        FrameBudget b(30.0);
        b.reportRows(40.0, 180);
        QCOMPARE(b.previewDivisor(180), 1);
        QCOMPARE(b.previewDivisor(180, 7 * 180), 1); // the filtering not measured yet
        b.reportDenoiseRows(10.0, 126);
        QCOMPARE(b.previewDivisor(180, 7 * 180), 3);
        QCOMPARE(b.previewDivisor(180), 1); // not filtered: no preview
    }

    void paintsStopAtTheBudget() {
        const FrameBudget b(30.0);
        QVERIFY(b.anotherFits(10.0, 10.0));
        QVERIFY(b.anotherFits(20.0, 10.0));
        QVERIFY(!b.anotherFits(21.0, 10.0));
        QVERIFY(!b.anotherFits(10.0, 2.0, 21.0)); // a short last step: the planned band decides
    }

    // The mean's filter: first steps of 1/16 of the image's rows, then rows of its stages at
    // 80 % of the budget from the measured cost (0.25 ms a row: 96 rows, 24 ms planned).
    void denoiseStepsFollowTheirRowCost() {
        FrameBudget b(30.0);
        QCOMPARE(b.denoiseRowsPerFrame(720), 720 / FrameBudget::kFirstBands);
        QCOMPARE(b.plannedMs(720, true), 0.0); // unmeasured
        b.reportDenoiseRows(12.0, 48);
        QCOMPARE(b.msPerDenoiseRow(), 0.25);
        QCOMPARE(b.denoiseRowsPerFrame(720), 96);
        QCOMPARE(b.plannedMs(720, true), 24.0);
        QCOMPARE(b.msPerRow(), -1.0); // the path tracer's rows are another cost
        b.reportRows(10.0, 10);
        QCOMPARE(b.plannedMs(720, false), 24.0); // bands of 24 rows at 1 ms
        b.reportDenoiseRows(1000.0, 1); // a stall: at least one row still
        QCOMPARE(b.denoiseRowsPerFrame(720), 1);
    }
};

QTEST_APPLESS_MAIN(TestViewportBudget)
#include "test_viewport_budget.moc"
