package dev.strahl.units;

/** Renders work units of one job on this member; safe to call from several threads at once. */
public interface UnitRenderer {
    /**
     * Renders the unit's samples, going on from the state it carries, and leaves the new state in it.
     *
     * @param unit the unit, updated in place
     */
    void render(WorkUnit unit);
}
