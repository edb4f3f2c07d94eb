package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;

/**
 * One light sample of next-event estimation between {@link DirectLight#prepare} and
 * {@link DirectLight#resolve}: what it adds to the radiance if nothing blocks it, and the shadow
 * ray that decides whether something does.
 */
public final class ShadowQuery {
    /** The shadow ray, when {@link #traced}. */
    public final Ray ray = new Ray();
    /** beta · f · Le · |cosθi| · w · scale / pdf: added where the shadow ray is not blocked. */
    public final MutableRgb contribution = new MutableRgb();
    /** Whether the shadow ray decides (false: the teaching option without shadows counts every sample). */
    public boolean traced;
    /** Whether a query was made and awaits {@link DirectLight#resolve}. */
    public boolean pending;
}
